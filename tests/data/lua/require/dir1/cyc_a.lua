return require("cyc_b")
