# Generates the teaching notebook from this source (run from the repository root).
import nbformat as nbf

nb = nbf.v4.new_notebook()
md = nbf.v4.new_markdown_cell
code = nbf.v4.new_code_cell
nb.cells = [
md("""# 1 · Zone tables: the grinder's stepped limit-value table

A cylindrical grinder holds the part between the work-head spindle and the tailstock; a rotary
dresser sits behind the spindle. The grinding wheel may come down to the part only between spindle
and tailstock. Over the work head it has to stay above the head, over the dresser it may come down
to dressing height only. The wheel's allowed area is therefore the region *above a stepped
boundary* — the shape the limit-value table of the grinder patent describes.

In this notebook you will
* load the grinder's machine file and look at its table,
* see why per-axis travel limits (a rectangle) cannot describe it,
* test points exactly — boundary points included — and
* count the comparisons the controller makes to find a region."""),
code("""from fractions import Fraction as F
import matplotlib.pyplot as plt
from nczones import load_machine, format_decimal
from nczones.commands.check_machine import describe_machine
from nczones.report.plot import plot_zones

grinder = load_machine("../specs/machines/grinder.toml")
print(describe_machine(grinder))"""),
md("""The table has one row per region of the reference axis X. Region *i* covers
`upto[i-1] < X <= upto[i]` (the first region also includes `from`), and inside it the limited
axis Y must lie between that row's `min` and `max`."""),
code("""ax = plot_zones(grinder)
plt.show()"""),
md("""## Why a rectangle cannot describe it

Conventional stroke limits give every axis one range, so the allowed area is a rectangle. The
smallest rectangle that contains the grinder's allowed area is its bounding box. Compare the two
areas, exactly:"""),
code("""table = grinder.zones[0]
(x_lo, x_hi), (y_lo, y_hi) = table.bounds()["X"], table.bounds()["Y"]
box_area = (x_hi - x_lo) * (y_hi - y_lo)
allowed_area = sum((r.upto - table.region_lower(i)) * (r.max - r.min) for i, r in enumerate(table.regions))
print(f"bounding box area : {format_decimal(box_area)} mm^2")
print(f"allowed area      : {format_decimal(allowed_area)} mm^2")
print(f"a rectangle would allow {format_decimal(box_area - allowed_area)} mm^2 the wheel must never enter "
      f"({format_decimal(100 * (box_area - allowed_area) / box_area, 1)} % of the box)")"""),
md("""A point the rectangle allows but the table forbids: the wheel low over the work head."""),
code("""over_head = {"X": F(300), "Y": F(100)}
print("inside the bounding box:", x_lo <= over_head["X"] <= x_hi and y_lo <= over_head["Y"] <= y_hi)
print("inside the allowed set :", grinder.allowed.contains(over_head))"""),
md("""## Exact membership, boundaries included

Numbers are exact rationals: the decimal text of the machine file and of the program becomes a
`Fraction`, never a float. A region's upper bound belongs to that region, so the step's corner
behaves exactly as the table says — one micron matters."""),
code("""def show(x, y):
    p = {"X": F(x), "Y": F(y)}
    region, comparisons = table.region_sequential(p["X"])
    where = "outside the table" if region is None else f"region {region + 1}"
    print(f"X{x:>9} Y{y:>7}: {where:<18} allowed={grinder.allowed.contains(p)}")

boundary = format_decimal(table.regions[0].upto)
step = format_decimal(table.regions[1].min)
show(boundary, format_decimal(table.regions[0].min))            # on the first region's floor at its last X
show(format_decimal(table.regions[0].upto + F(1, 1000)), format_decimal(table.regions[0].min))  # one micron further
show(format_decimal(table.regions[0].upto + F(1, 1000)), step)  # ... at the second region's floor
show(format_decimal(table.start - F(1, 1000)), "250")           # before 'from'"""),
md("""## The controller's lookup: sequential comparison

A controller's monitor routine finds the region the way the patent describes: compare the reference
coordinate with `from`, then with each boundary in turn until it is not greater, and read that row.
That takes at most *regions + 1* comparisons. A binary search (`bisect`) finds the same region in
logarithmically many steps; both must agree everywhere."""),
code("""import random
rng = random.Random(7)
xs = [F(rng.randint(-50_000, 1_250_000), 1000) for _ in range(20_000)] + [table.start, *table.uptos]
worst = 0
for x in xs:
    seq, comparisons = table.region_sequential(x)
    assert seq == table.region_bisect(x)
    worst = max(worst, comparisons)
print(f"{len(xs)} reference values: sequential == bisect everywhere; "
      f"at most {worst} comparisons for {len(table.regions)} regions")"""),
code("""counts = [table.region_sequential(F(x))[1] for x in range(-20, 1221, 5)]
fig, ax = plt.subplots(figsize=(7, 2.5))
ax.step(range(-20, 1221, 5), counts, where="post")
ax.set_xlabel("X (mm)"); ax.set_ylabel("comparisons"); ax.set_title("Comparisons per lookup along X")
plt.show()"""),
md("""## Exercises

1. Add a fifth region to a copy of `grinder.toml` for a steady rest between spindle and tailstock,
   and plot it. What does `nczones check-machine` say if its `upto` is not increasing?
2. Which points of the step corners belong to which region? Test both sides of every `upto` with
   `table.region_sequential`.
3. A table with 256 regions: how many comparisons does the worst lookup take sequentially, and how
   many with bisection? Build one with `nczones.testing.zone_tables` and count."""),
]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbf.write(nb, "notebooks/01_zone_tables.ipynb")
