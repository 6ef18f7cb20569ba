-- must stop: no require, no package
local os = require("os")
os.execute("touch hostile-was-here")
