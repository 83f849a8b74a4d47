return { name = "second" }
