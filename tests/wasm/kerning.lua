-- The kerning of labels composed in a course page (tests/wasm/page.mjs):
-- text with kerned pairs (AV, VA, AT, To, Wa, LT: Latin Modern Roman
-- moves them together) that a slider changes, so that at another value
-- the page composes it from its characters, and mathematics beside it.
local t = slider{ name = "t", min = 0, max = 1, default = 0.5, step = 0.01 }
local f = figure{
  name = "kerning", width = "8cm", height = "4cm", page = "fixed",
  window = { 0, 10, 0, 5 },
}
f:polyline({ { 0, 0 }, { 10, 1 } })
f:label({ 1, 4 }, string.format("AVATAR To Wa, LTA %.2f $P_0 = c(%.2f)$",
                                t, t), { place = "e" })
f:label({ 1, 2.5 }, string.format("VAT %.2f", 1 - t), { place = "e" })
