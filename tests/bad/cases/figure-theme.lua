-- expect: 1 "figure: theme "neon" is unknown; the names are "default" or "mono""
-- an unknown theme
local f = figure{ name = 'z', theme = 'neon' }
