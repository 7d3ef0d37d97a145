#!/usr/bin/python3
"""Picture helpers for tools/screenshots (needs PIL: run with /usr/bin/python3).

  --row N PNG             x y of the Nth menu row (1 = first) of a centred menu, for the mouse
  --check PNG...          each picture is not blank and its text rows stay off its edges
  --deuteranopia A B OUT  A and B side by side, over the same two as a deuteranope sees them
  --fit WIDTH IN OUT      IN scaled down to at most WIDTH pixels wide, in 256 colours

The deuteranopia simulation is Machado, Oliveira and Fernandes (2009), "A Physiologically-based
Model for Simulation of Color Vision Deficiency", IEEE TVCG 15(6): their matrix for
deuteranomaly at severity 1.0 (deuteranopia), applied to linear RGB.
"""
import sys

from PIL import Image, ImageDraw

MACHADO_DEUTERANOPIA = (
    (0.367322, 0.860646, -0.227968),
    (0.280085, 0.672501, 0.047413),
    (-0.011820, 0.042940, 0.968881),
)


def to_linear(c):
    c /= 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def to_srgb(c):
    c = min(max(c, 0.0), 1.0)
    c = c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return round(c * 255.0)


def simulate_deuteranopia(img):
    lin = [to_linear(float(i)) for i in range(256)]
    rgb = img.convert("RGB")
    px = rgb.load()
    out = Image.new("RGB", rgb.size)
    opx = out.load()
    m = MACHADO_DEUTERANOPIA
    cache = {}
    for y in range(rgb.size[1]):
        for x in range(rgb.size[0]):
            p = px[x, y]
            q = cache.get(p)
            if q is None:
                r, g, b = lin[p[0]], lin[p[1]], lin[p[2]]
                q = tuple(to_srgb(row[0] * r + row[1] * g + row[2] * b) for row in m)
                cache[p] = q
            opx[x, y] = q
    return out


def bands(img, x0, x1, y0, y1, threshold=90):
    """Runs of rows in [y0, y1) with a bright pixel between x0 and x1."""
    g = img.convert("L")
    px = g.load()
    lit = [any(px[x, y] > threshold for x in range(x0, x1)) for y in range(y0, y1)]
    runs, start = [], None
    for i, on in enumerate(lit + [False]):
        if on and start is None:
            start = i
        elif not on and start is not None:
            if i - start >= 3:
                runs.append((y0 + start, y0 + i))
            start = None
    return runs


def menu_row(path, n):
    """The selected row (drawn white, the others green) is row 1; the rows below it follow."""
    img = Image.open(path).convert("RGB")
    w, h = img.size
    px = img.load()
    x0, x1 = int(w * 0.4), int(w * 0.6)
    white = [y for y in range(h // 3, int(h * 0.92))
             if any(min(px[x, y][0], px[x, y][2]) > 170 for x in range(x0, x1, 2))]
    if not white:
        sys.exit(f"{path}: no selected (white) menu row")
    runs = [r for r in bands(img, x0, x1, white[0] - 2, int(h * 0.92), 150) if r[1] - r[0] >= 6]
    if len(runs) < n:
        sys.exit(f"{path}: {len(runs)} menu rows found, not {n}")
    a, b = runs[n - 1]
    print(w // 2, (a + b) // 2)


def check(paths):
    bad = 0
    for path in paths:
        img = Image.open(path).convert("L")
        w, h = img.size
        lit = sum(1 for v in img.getdata() if v > 40)
        if lit < w * h // 2000:
            print(f"{path}: blank ({lit} lit pixels)")
            bad += 1
            continue
        # Text along the bottom (footer, hints) and top (title, score) must not run off the
        # sides: the outer 0.5% columns of those strips stay dark.
        px = img.load()
        edge = max(2, w // 200)
        for y0, y1 in ((0, h // 12), (h - h // 10, h)):
            for x in list(range(edge)) + list(range(w - edge, w)):
                if any(px[x, y] > 120 for y in range(y0, y1)):
                    print(f"{path}: something bright at the edge, x {x}, rows {y0}-{y1}")
                    bad += 1
                    break
        print(f"{path}: {w}x{h}, {lit} lit pixels")
    sys.exit(1 if bad else 0)


def deuteranopia(a_path, b_path, out_path):
    a, b = Image.open(a_path).convert("RGB"), Image.open(b_path).convert("RGB")
    size = (640, 360)
    a, b = a.resize(size, Image.LANCZOS), b.resize(size, Image.LANCZOS)
    sheet = Image.new("RGB", (size[0] * 2 + 10, size[1] * 2 + 60), (40, 40, 40))
    draw = ImageDraw.Draw(sheet)
    labels = ("default", "colour-safe", "default, deuteranopia", "colour-safe, deuteranopia")
    for i, img in enumerate((a, b, simulate_deuteranopia(a), simulate_deuteranopia(b))):
        x = (i % 2) * (size[0] + 10)
        y = (i // 2) * (size[1] + 30) + 20
        sheet.paste(img, (x, y))
        draw.text((x + 4, y - 16), labels[i], fill=(230, 230, 230))
    sheet.save(out_path, optimize=True)
    simulate_deuteranopia(Image.open(a_path)).save(out_path.replace(".png", "_default.png"))
    simulate_deuteranopia(Image.open(b_path)).save(out_path.replace(".png", "_colour_safe.png"))


def fit(width, in_path, out_path):
    img = Image.open(in_path).convert("RGB")
    if img.size[0] > width:
        img = img.resize((width, round(img.size[1] * width / img.size[0])), Image.LANCZOS)
    # 256 colours keep glowing lines on black looking the same at a third of the bytes.
    img.quantize(256, method=Image.Quantize.MEDIANCUT).save(out_path, optimize=True)


def main(argv):
    if len(argv) == 3 and argv[0] == "--row":
        menu_row(argv[2], int(argv[1]))
    elif len(argv) >= 2 and argv[0] == "--check":
        check(argv[1:])
    elif len(argv) == 4 and argv[0] == "--deuteranopia":
        deuteranopia(*argv[1:])
    elif len(argv) == 4 and argv[0] == "--fit":
        fit(int(argv[1]), argv[2], argv[3])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
