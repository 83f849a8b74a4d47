return require("cyc_a")
