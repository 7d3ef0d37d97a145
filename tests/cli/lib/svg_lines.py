#!/usr/bin/python3
"""Checks and rasterises the SVG that `beamzone render --svg` writes (used by svg_export.sh).

  svg_lines.py check FILE.svg W H          parse with a real XML parser, check the structure,
                                           print "groups NAME=PATHS ... paths N points N"
  svg_lines.py hairline FILE.svg OUT.svg   the visible lines 0.2 px wide (thinner ones fall between the rasteriser's
                                           coverage samples), no background, HUD nor hidden lines, so a
                                           rasteriser lights (nearly) only the pixels they cross
  svg_lines.py mask IN.png OUT.png         any pixel with alpha > 0 -> 255, else 0 (8-bit gray)
"""
import re
import sys
import xml.etree.ElementTree as ET

from PIL import Image

SVG = "{http://www.w3.org/2000/svg}"
KINDS = {"silhouette", "crease", "boundary", "material", "intersection", "hud", "hidden-1", "hidden-2", "hidden-3"}
NUMBER = r"-?\d+(?:\.\d+)?"
PATH_D = re.compile(rf"^M {NUMBER} {NUMBER}(?: L(?: {NUMBER} {NUMBER})+)?$")
COLOUR = re.compile(r"^#[0-9a-f]{6}$")


def fail(msg):
    print(f"svg_lines.py: {msg}", file=sys.stderr)
    sys.exit(1)


def check(path, width, height):
    root = ET.parse(path).getroot()
    if root.tag != SVG + "svg":
        fail(f"root element is {root.tag}, not svg")
    if root.get("version") != "1.1":
        fail("no version 1.1")
    if root.get("width") != width or root.get("height") != height:
        fail(f"size {root.get('width')}x{root.get('height')}, wanted {width}x{height}")
    if root.get("viewBox") != f"0 0 {width} {height}":
        fail(f"viewBox {root.get('viewBox')}")
    counts, points = {}, 0
    for child in root:
        if child.tag == SVG + "rect":
            continue
        if child.tag != SVG + "g":
            fail(f"unexpected element {child.tag}")
        gid = child.get("id")
        if gid not in KINDS or gid in counts:
            fail(f"unexpected or repeated group {gid}")
        if not COLOUR.match(child.get("stroke", "")) or child.get("fill") != "none":
            fail(f"group {gid}: stroke {child.get('stroke')} fill {child.get('fill')}")
        if float(child.get("stroke-width", "0")) <= 0:
            fail(f"group {gid}: no stroke width")
        counts[gid] = 0
        for p in child:
            if p.tag != SVG + "path":
                fail(f"group {gid} holds {p.tag}")
            d = p.get("d", "")
            if not PATH_D.match(d):
                fail(f"bad path data {d[:80]!r}")
            if p.get("stroke") is not None and not COLOUR.match(p.get("stroke")):
                fail(f"bad path stroke {p.get('stroke')}")
            if gid.startswith("hidden-"):
                if not re.match(r"^\d+ \d+$", child.get("stroke-dasharray", "")):
                    fail(f"group {gid} is not dashed")
                float(p.get("stroke-dashoffset"))  # every hidden path anchors its dashes
            nums = [float(v) for v in re.findall(NUMBER, d)]
            for x, y in zip(nums[0::2], nums[1::2]):
                if not (-2 <= x <= float(width) + 2 and -2 <= y <= float(height) + 2):
                    fail(f"point {x},{y} off the canvas")
            points += len(nums) // 2
            counts[gid] += 1
    groups = " ".join(f"{k}={v}" for k, v in counts.items())
    print(f"groups {groups} paths {sum(counts.values())} points {points}")


def hairline(path, out):
    ET.register_namespace("", SVG[1:-1])
    ET.register_namespace("inkscape", "http://www.inkscape.org/namespaces/inkscape")
    tree = ET.parse(path)
    root = tree.getroot()
    for child in list(root):
        if child.tag == SVG + "rect" or child.get("id") == "hud" or \
                child.get("id", "").startswith("hidden-"):
            root.remove(child)  # the reference mask has neither HUD nor hidden lines
        elif child.tag == SVG + "g":
            child.set("stroke-width", "0.2")
    tree.write(out, xml_declaration=True, encoding="UTF-8")


def mask(src, out):
    img = Image.open(src).convert("RGBA")
    alpha = img.getchannel("A")
    alpha.point(lambda a: 255 if a > 0 else 0).save(out)


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "check":
        check(sys.argv[2], sys.argv[3], sys.argv[4])
    elif len(sys.argv) == 4 and sys.argv[1] == "hairline":
        hairline(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "mask":
        mask(sys.argv[2], sys.argv[3])
    else:
        fail(__doc__)
