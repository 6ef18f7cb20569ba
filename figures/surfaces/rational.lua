-- surfaces/rational: a biquadratic rational patch, the weight of its
-- middle control point P_11 1 in panel (a) and 4 in panel (b), the same
-- net and the same view: the raised weight pulls the surface towards
-- P_11.

local P = {
  { {0, 0, 0},   {0, 1.5, 0.5}, {0, 3, 0} },
  { {1.5, 0, 0.5}, {1.5, 1.5, 2.5}, {1.5, 3, 0.5} },
  { {3, 0, 0},   {3, 1.5, 0.5}, {3, 3, 0} },
}

local f = figure{
  name = "surfaces-rational",
  caption = "A biquadratic rational patch with the weight of P_{11} 1 "
    .. "(left) and 4 (right), the same net and view",
  width = "12cm", height = "5.5cm",
}
local panels = { f:panels{ rows = 1, cols = 2,
                           titles = { "w_{11} = 1", "w_{11} = 4" } } }
for k, w in ipairs({ 1, 4 }) do
  local p = panels[k]
  p:view(-60, 25)
  local s = bezier_surface{ points = P,
                            weights = { { 1, 1, 1 }, { 1, w, 1 },
                                        { 1, 1, 1 } } }
  p:surface(s, { isolines = { 3, 3 }, hidden = "dashed",
                 net = { color = "grey" }, label_place = "n",
                 labels = function(i, j)
                   if i == 1 and j == 1 then return "P_{11}" end
                 end })
end
