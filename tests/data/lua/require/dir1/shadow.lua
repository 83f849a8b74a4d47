return "dir1"
