-- cyc_a requires cyc_b, which requires cyc_a again.
return require("cyc_a")
