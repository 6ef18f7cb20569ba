-- expect: 1 "theme: palette "okabe_ito" is unknown (did you mean "okabe-ito"?)"
-- a palette name misspelt: the error names the nearest
theme{ palette = "okabe_ito" }
