std = "luajit"
codes = true
max_line_length = 120
-- busted's globals only in specs
files["Tests/**/*_spec.lua"] = { std = "+busted" }
exclude_files = { "build/**" }
