#!/usr/bin/env python3
"""Writes the OBJ models the shipped levels use. Every shape is built here from boxes,
prisms and lathed profiles, each a closed surface with outward (counter-clockwise) faces, so
the line renderer finds clean silhouettes and creases. Run from anywhere: python3 generate.py
Units are world units (the built-in cube is 5 high); y is up and every model stands on y = 0."""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


class Mesh:
    def __init__(self):
        self.v = []
        self.f = []
        self.groups = []  # (name, first face index)

    def group(self, name):
        self.groups.append((name, len(self.f)))

    def add(self, verts, faces):
        base = len(self.v)
        self.v.extend(verts)
        self.f.extend(tuple(base + i for i in face) for face in faces)

    def write(self, name, comment):
        path = os.path.join(HERE, name)
        with open(path, "w") as out:
            out.write(f"# {name}: {comment}\n")
            out.write("# Original to beamzone (data/models/generate.py); see README.md.\n")
            tris = sum(len(f) - 2 for f in self.f)
            out.write(f"# {len(self.v)} vertices, {tris} triangles\n")
            for x, y, z in self.v:
                out.write(f"v {x:.4f} {y:.4f} {z:.4f}\n")
            starts = dict((start, g) for g, start in self.groups)
            for i, face in enumerate(self.f):
                if i in starts:
                    out.write(f"o {starts[i]}\n")
                out.write("f " + " ".join(str(k + 1) for k in face) + "\n")
        return tris


def rot_y(p, a):
    c, s = math.cos(a), math.sin(a)
    x, y, z = p
    return (c * x + s * z, y, -s * x + c * z)


def rot_x(p, a):
    c, s = math.cos(a), math.sin(a)
    x, y, z = p
    return (x, c * y - s * z, s * y + c * z)


def rot_z(p, a):
    c, s = math.cos(a), math.sin(a)
    x, y, z = p
    return (c * x - s * y, s * x + c * y, z)


def moved(verts, fn):
    return [fn(p) for p in verts]


def box(hx, hy, hz):
    """Axis-aligned box centred on the origin."""
    v = [(x, y, z) for x in (-hx, hx) for y in (-hy, hy) for z in (-hz, hz)]
    # index = 4*ix + 2*iy + iz
    f = [(0, 1, 3, 2), (4, 6, 7, 5),  # -x, +x
         (0, 4, 5, 1), (2, 3, 7, 6),  # -y, +y
         (0, 2, 6, 4), (1, 5, 7, 3)]  # -z, +z
    return v, f


def lathe(profile, sides, phase=0.0):
    """Closed surface of revolution about +y. profile: (radius, y) from bottom to top; ends
    with radius 0 become poles, others get flat caps."""
    v, f = [], []
    rings = []
    for r, y in profile:
        if r == 0:
            rings.append([len(v)])
            v.append((0.0, y, 0.0))
        else:
            ring = []
            for k in range(sides):
                a = phase + 2 * math.pi * k / sides
                ring.append(len(v))
                v.append((r * math.cos(a), y, -r * math.sin(a)))
            rings.append(ring)
    for lo, hi in zip(rings, rings[1:]):
        for k in range(sides):
            k2 = (k + 1) % sides
            if len(lo) == 1:
                f.append((lo[0], hi[k], hi[k2]))
            elif len(hi) == 1:
                f.append((lo[k], lo[k2], hi[0]))
            else:
                f.append((lo[k], lo[k2], hi[k2], hi[k]))
    if len(rings[0]) > 1:
        f.append(tuple(reversed(rings[0])))
    if len(rings[-1]) > 1:
        f.append(tuple(rings[-1]))
    return v, f


def triangulate(faces):
    out = []
    for face in faces:
        for i in range(1, len(face) - 1):
            out.append((face[0], face[i], face[i + 1]))
    return out


def pylon():
    m = Mesh()
    # Tapered lattice tower stand-in: a square frustum (4-sided lathe) with a waist.
    m.group("tower")
    v, f = lathe([(3.2, 0), (2.0, 7), (1.1, 13), (0.8, 16), (0, 17.5)], 4, math.pi / 4)
    m.add(v, triangulate(f))
    for y, half in ((12.5, 6.0), (9.5, 4.5)):
        m.group(f"arm_{y}")
        v, f = box(half, 0.35, 0.5)
        m.add(moved(v, lambda p, y=y: (p[0], p[1] + y, p[2])), triangulate(f))
        # Insulators hang from the arm tips.
        for side in (-1, 1):
            v, f = lathe([(0.35, 0), (0.35, 1.6), (0, 1.6)], 6)
            m.add(moved(v, lambda p, y=y, side=side: (p[0] + side * (half - 0.4), p[1] + y - 1.95, p[2])),
                  triangulate(f))
    return m


def radar_dish():
    m = Mesh()
    m.group("base")
    v, f = box(2.2, 0.6, 2.2)
    m.add(moved(v, lambda p: (p[0], p[1] + 0.6, p[2])), triangulate(f))
    m.group("mast")
    v, f = lathe([(0.6, 1.2), (0.45, 5.2), (0, 5.6)], 8)
    m.add(v, triangulate(f))
    m.group("dish")
    # A shallow paraboloid shell with thickness: outer skin, inner skin, joined at the rim.
    rings, sides, radius, depth, thick = 6, 16, 3.6, 1.2, 0.18
    profile = []
    for i in range(rings + 1):
        r = radius * i / rings
        profile.append((r, depth * (r / radius) ** 2))
    outer = [(r, y - thick) for r, y in profile]
    inner = list(reversed(profile))
    shape = outer + inner
    v, f = [], []
    ring_ids = []
    for r, y in shape:
        if r == 0:
            ring_ids.append([len(v)])
            v.append((0.0, y, 0.0))
        else:
            ids = []
            for k in range(sides):
                a = 2 * math.pi * k / sides
                ids.append(len(v))
                v.append((r * math.cos(a), y, -r * math.sin(a)))
            ring_ids.append(ids)
    for lo, hi in zip(ring_ids, ring_ids[1:]):
        for k in range(sides):
            k2 = (k + 1) % sides
            if len(lo) == 1:
                f.append((lo[0], hi[k], hi[k2]))
            elif len(hi) == 1:
                f.append((lo[k2], lo[k], hi[0]))
            else:
                f.append((lo[k], hi[k], hi[k2], lo[k2]))
    tilt = math.radians(35)
    m.add(moved(v, lambda p: (lambda q: (q[0], q[1] + 6.2, q[2]))(rot_x(p, tilt))), triangulate(f))
    m.group("feed")
    v, f = box(0.12, 1.1, 0.12)
    m.add(moved(v, lambda p: (lambda q: (q[0], q[1] + 6.2, q[2]))(rot_x((p[0], p[1] + 1.1, p[2]), tilt))),
          triangulate(f))
    return m


def ruined_tower():
    m = Mesh()
    m.group("wall")
    # A round tower, broken off at a different height on every side: each column of the
    # lathe gets its own top.
    sides, r_out, r_in = 12, 3.6, 2.8
    tops = [11.0, 12.5, 10.2, 7.5, 5.8, 6.6, 9.0, 8.1, 10.8, 13.2, 12.0, 11.4]
    v, f = [], []
    for k in range(sides):
        a0 = 2 * math.pi * k / sides
        a1 = 2 * math.pi * (k + 1) / sides
        h = tops[k]
        # One closed wedge block per side: outer and inner arcs, bottom and broken top.
        pts = []
        for r, a in ((r_out, a0), (r_out, a1), (r_in, a1), (r_in, a0)):
            pts.append((r * math.cos(a), -r * math.sin(a)))
        base = len(v)
        for x, z in pts:
            v.append((x, 0.0, z))
        for i, (x, z) in enumerate(pts):
            v.append((x, h - (0.9 if i % 2 else 0.0), z))
        f.extend([(base + 3, base + 2, base + 1, base + 0),
                  (base + 4, base + 5, base + 6, base + 7),
                  (base + 0, base + 1, base + 5, base + 4),
                  (base + 1, base + 2, base + 6, base + 5),
                  (base + 2, base + 3, base + 7, base + 6),
                  (base + 3, base + 0, base + 4, base + 7)])
    m.add(v, triangulate(f))
    for i, (x, z, s, a) in enumerate(((4.8, 1.5, 0.9, 0.3), (3.9, -3.4, 0.6, 1.1), (-4.9, 2.2, 0.7, 2.0))):
        m.group(f"rubble_{i}")
        v, f = box(s * 1.2, s * 0.6, s)
        m.add(moved(v, lambda p, x=x, z=z, s=s, a=a: (lambda q: (q[0] + x, q[1] + s * 0.6, q[2] + z))(rot_y(p, a))),
              triangulate(f))
    return m


def tank_hulk():
    # A wreck must never read as a live enemy tank: the hull lies broken-backed and rolled
    # onto one track, sunk into the ground, and the turret lies upside down beside it with a
    # snapped stub of a barrel, so the tank outline (turret on hull, long gun) never appears.
    m = Mesh()
    hw = 2.0

    def hull_half(x0, x1, tilt, shift):
        # One half of the broken hull: a slab of the side profile between x0 and x1, rolled
        # over onto its side and tipped so the break points up out of the ground.
        prof = [(x0, 0.0), (x1, 0.0), (x1 + (0.8 if x1 > 0 else 0.0), 0.9),
                (x1 - (0.4 if x1 > 0 else 0.0), 1.5), (x0, 1.5)]
        v = [(x, y, -hw) for x, y in prof] + [(x, y, hw) for x, y in prof]
        n = len(prof)
        f = [tuple(reversed(range(n))), tuple(range(n, 2 * n))]
        for i in range(n):
            j = (i + 1) % n
            f.append((i, j, n + j, n + i))
        v = moved(v, lambda p: rot_x(rot_z(p, tilt), 0.45))
        # Sunk just below the ground: nothing hides a part that would poke out underneath.
        drop = min(p[1] for p in v) + 0.2
        v = moved(v, lambda p: (p[0] + shift, p[1] - drop, p[2]))
        return v, triangulate(f)

    m.group("hull_front")
    m.add(*hull_half(0.2, 3.4, -0.28, 0.3))
    m.group("hull_back")
    m.add(*hull_half(-3.4, -0.2, 0.22, -0.3))
    m.group("turret")
    # Upside down on the ground off the hull's flank: flat top down, wide base up.
    v, f = lathe([(1.3, 0), (1.7, 1.1), (0, 1.1)], 8, math.pi / 8)
    m.add(moved(v, lambda p: (p[0] - 1.0, p[1], p[2] + 3.7)), triangulate(f))
    m.group("barrel_stub")
    # A short snapped-off piece lying flat, pointing away from the turret.
    v, f = box(0.6, 0.16, 0.16)
    m.add(moved(v, lambda p: (lambda q: (q[0] + 1.2, q[1] + 0.16, q[2] + 4.3))(rot_y(p, 0.9))),
          triangulate(f))
    return m


def main():
    made = {
        "pylon.obj": (pylon(), "power pylon, 17.5 high, 12 across the upper arm"),
        "radar_dish.obj": (radar_dish(), "radar dish on a mast, tilted 35 degrees, about 9 high"),
        "ruined_tower.obj": (ruined_tower(), "round tower broken off at uneven heights, with rubble"),
        "tank_hulk.obj": (tank_hulk(), "broken tank hull on its side, turret upside down beside it"),
    }
    for name, (mesh, comment) in made.items():
        tris = mesh.write(name, comment)
        print(f"{name}: {len(mesh.v)} vertices, {tris} triangles")


if __name__ == "__main__":
    main()
