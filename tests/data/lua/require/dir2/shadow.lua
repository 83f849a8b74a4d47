return "dir2"
