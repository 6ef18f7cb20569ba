-- expect: 1 "figure: a figure named "f1" is already defined"
-- 30,000 figures, then a name used again (each name was compared with every figure before it)
-- args: --timeout 30
-- command: list
for i = 1, 30000 do figure{ name = "f" .. i } end
figure{ name = "f1" }
