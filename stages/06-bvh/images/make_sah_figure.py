#!/usr/bin/env python3
"""Draws sah_binning.svg for the stage 06 handout: twelve primitives in 2D, their centroids
binned along x into 8 bins, and the SAH cost of each of the 7 candidate splits.
The costs are computed here with the same formula as the handout (2D: perimeter instead of
surface area), so the picture cannot disagree with the text. Run: python3 make_sah_figure.py"""

BOXES = [  # (x0, y0, x1, y1) in a 0..100 x 0..60 world
    (2, 30, 10, 42), (6, 8, 16, 20), (12, 40, 20, 52), (14, 22, 22, 34),
    (20, 6, 28, 14), (24, 44, 30, 56), (62, 10, 74, 30), (66, 36, 80, 50),
    (72, 20, 84, 34), (78, 4, 90, 16), (84, 40, 96, 54), (88, 26, 98, 38)]
BINS, C_TRAV = 8, 1.0


def union(boxes):
    return (min(b[0] for b in boxes), min(b[1] for b in boxes),
            max(b[2] for b in boxes), max(b[3] for b in boxes))


def perimeter(b):
    return 2 * ((b[2] - b[0]) + (b[3] - b[1]))


def center_x(b):
    return (b[0] + b[2]) / 2


node = union(BOXES)
lo, hi = min(map(center_x, BOXES)), max(map(center_x, BOXES))


def bin_of(c):
    return min(BINS - 1, max(0, int(BINS * (c - lo) / (hi - lo))))


costs = []
for k in range(1, BINS):
    left = [b for b in BOXES if bin_of(center_x(b)) < k]
    right = [b for b in BOXES if bin_of(center_x(b)) >= k]
    if not left or not right:
        costs.append(None)
        continue
    costs.append(C_TRAV + (perimeter(union(left)) * len(left) +
                           perimeter(union(right)) * len(right)) / perimeter(node))
best = min((c, k) for k, c in enumerate(costs, 1) if c is not None)[1]

S, W, H = 6, 100, 60  # pixels per unit, world size
out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">'
       % (W * S + 40, H * S + 270)]
out.append('<rect width="100%" height="100%" fill="white"/>')
ox, oy = 20, 20
# Bins (centroid range split in BINS equal parts), candidate planes, the chosen one in red.
for k in range(BINS + 1):
    x = ox + S * (lo + (hi - lo) * k / BINS)
    colour, width = ("#d62728", 3) if k == best else ("#999", 1)
    dash = "" if k == best else ' stroke-dasharray="4 3"'
    out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="%s" stroke-width="%d"%s/>'
               % (x, oy - 8, x, oy + H * S + 8, colour, width, dash))
for b in BOXES:
    left = bin_of(center_x(b)) < best
    fill = "#9ecae1" if left else "#fdae6b"
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="%s" stroke="#333"/>'
               % (ox + S * b[0], oy + S * b[1], S * (b[2] - b[0]), S * (b[3] - b[1]), fill))
    out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="#000"/>'
               % (ox + S * center_x(b), oy + S * (b[1] + b[3]) / 2))
for side, colour in ((True, "#3182bd"), (False, "#e6550d")):
    u = union([b for b in BOXES if (bin_of(center_x(b)) < best) == side])
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="%s" stroke-width="2"/>'
               % (ox + S * u[0] - 3, oy + S * u[1] - 3, S * (u[2] - u[0]) + 6, S * (u[3] - u[1]) + 6, colour))
# Cost of each candidate as bars under its plane.
base = oy + H * S + 220
scale = 150 / max(c for c in costs if c is not None)
out.append('<text x="%d" y="%d">SAH cost C_trav + (P_L N_L + P_R N_R) / P of splitting at each bin boundary; a leaf costs %d</text>'
           % (ox, oy + H * S + 40, len(BOXES)))
for k, c in enumerate(costs, 1):
    if c is None:
        continue
    x = ox + S * (lo + (hi - lo) * k / BINS)
    colour = "#d62728" if k == best else "#777"
    out.append('<rect x="%.1f" y="%.1f" width="16" height="%.1f" fill="%s"/>'
               % (x - 8, base - scale * c, scale * c, colour))
    out.append('<text x="%.1f" y="%d" text-anchor="middle">%.2f</text>' % (x, base + 16, c))
out.append('</svg>')
with open("sah_binning.svg", "w") as f:
    f.write("\n".join(out) + "\n")
print("best split after bin", best, "costs", ["-" if c is None else round(c, 2) for c in costs])
