-- sir-weierstrass (seed 000, Šír, "Bézierovy křivky", slide
-- "Bernsteinovy polynomy": "Pro každou funkci f(t) spojitou na intervalu
-- [0, 1] definujeme f_n(t) = Σ f(i/n) B_i^n(t). Pak platí f_n ⇉ f
-- (Bernstein 1912)").
-- The Bernstein approximations f_2, f_5, f_10, f_50 of one continuous
-- function converge uniformly to it.
-- Data chosen (the seed gives no f): f(t) = 1/4 + |t − 1/2| + sin(2πt)/4, a
-- continuous function that is not a polynomial (it has a kink at
-- t = 1/2, where the convergence is slowest, and an asymmetric wave).
-- f is drawn thick and black; f_2 dashed, f_5 dash-dotted, f_10 dotted,
-- f_50 solid thin, each in its own colour and labelled; the samples
-- f(i/10) used by f_10 are marked on f.

local function f(t) return 0.25 + math.abs(t - 0.5) + math.sin(2 * math.pi * t) / 4 end

local fig = figure{
  name = "sir-weierstrass",
  caption = "Bernstein approximation f_n = Σ f(i/n) B_i^n of the continuous "
    .. "f(t) = 1/4 + |t − 1/2| + sin(2πt)/4 for n = 2, 5, 10, 50, converging "
    .. "uniformly to f (Bernstein 1912); dots: the samples f(i/10), the "
    .. "control values of f_10",
  width = "10cm", height = "6.5cm",
}
fig:plot{ x = {0, 1}, y = {0, 0.9}, xticks = 0.25, yticks = { 0, 0.25, 0.5, 0.75 },
          xlabel = "t" }

local styles = {
  { n = 2,  color = 1, dash = "dashed" },
  { n = 5,  color = 2, dash = "dashdot" },
  { n = 10, color = 3, dash = "dotted" },
  { n = 50, color = 4, dash = "solid" },
}
for _, s in ipairs(styles) do
  fig:curve(bernstein_approx(f, s.n), { color = s.color, dash = s.dash, width = 1.3 })
end
fig:func(f, 0, 1, { color = "black", width = 2 })
local samples = {}
for i = 0, 10 do samples[#samples + 1] = { i / 10, f(i / 10) } end
fig:points(samples, { marker = "dot", marker_size = 3, color = "black",
                      marker_color = "black",
                      legend = "f(i/10)\\text{: koeficienty } f_{10}" })

-- labels: f at its crest; f_2 above its graph at t = 0.8; f_5 and f_10
-- centred in the gaps of the trough at t = 0.62 (each just above its own
-- graph, below the graph of the previous n); f_50 (close to f everywhere)
-- from the free space below the curves, with a pointer
fig:label({ 0.2, f(0.2) }, "f", { place = "n" })
fig:label(bernstein_approx(f, 2):eval(0.8), "f_2", { place = "n", color = 1 })
local t0 = 0.62
local y2 = bernstein_approx(f, 2):eval(t0)[2]
local y5 = bernstein_approx(f, 5):eval(t0)[2]
local y10 = bernstein_approx(f, 10):eval(t0)[2]
fig:label({ t0, (y2 + y5) / 2 + 0.005 }, "f_5", { place = "center", color = 2 })
fig:label({ t0, (y5 + y10) / 2 + 0.005 }, "f_{10}", { place = "center", color = 3 })
local q = bernstein_approx(f, 50):eval(0.5)
fig:arrow_to({ 0.36, 0.14 }, { q[1] - 0.005, q[2] - 0.01 }, { color = 4, width = 0.6 })
fig:label({ 0.36, 0.14 }, "f_{50}", { place = "w", color = 4 })
