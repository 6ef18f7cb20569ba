-- surfaces/rational: a rational biquadratic patch with the weight of its
-- middle control point raised from 1 to 4, which pulls the surface
-- towards that point; the polynomial patch (weights 1) in grey for
-- comparison.  Two views of the same patches: orthographic, and a
-- perspective from 7 units away (the projected lines are then rational
-- curves, still exact).

local P = {
  { {0, 0, 0},   {0, 1.5, 0.5}, {0, 3, 0} },
  { {1.5, 0, 0.5}, {1.5, 1.5, 2.5}, {1.5, 3, 0.5} },
  { {3, 0, 0},   {3, 1.5, 0.5}, {3, 3, 0} },
}
local W = { { 1, 1, 1 }, { 1, 4, 1 }, { 1, 1, 1 } }
local plain = bezier_surface{ points = P }
local raised = bezier_surface{ points = P, weights = W }

local views = {
  { view = { -60, 25 } },
  { view = { 10, 20 }, projection = "perspective", distance = 7,
    target = { 1.5, 1.5, 0.5 } },
}
for k, v in ipairs(views) do
  local f = figure{
    name = "surfaces-rational-" .. k,
    caption = "A rational biquadratic patch with w_{11} = 4 (dark) and the "
      .. "polynomial one (grey), view " .. k .. " of 2"
      .. (v.projection and " (perspective)" or ""),
    width = "7cm", height = "5.5cm",
    view = v.view, projection = v.projection, distance = v.distance,
    target = v.target,
  }
  f:surface(plain, { color = "#a0a0a0", width = 0.7, isolines = { 3, 3 },
                     occludes = false, hidden = "show" })
  f:surface(raised, { isolines = { 3, 3 }, hidden = "dashed",
                      net = { color = "grey" }, label_place = "n", labels = function(i, j)
                        if i == 1 and j == 1 then return "P_{11}" end
                      end })
end
