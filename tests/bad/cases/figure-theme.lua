-- expect: 1 "figure: theme: unknown theme "neon" (use default or mono)"
-- an unknown theme
local f = figure{ name = 'z', theme = 'neon' }
