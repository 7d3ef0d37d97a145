#!/usr/bin/env python3
"""Lays out the three shipped levels with too many objects to place by hand: maze.toml,
plains.toml and stress.toml. The output is ordinary level TOML; edit it by hand afterwards
like any other level (running this again overwrites those edits). The layouts are seeded, so
a run reproduces the committed files exactly. Usage: python3 levels/generate.py"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = "../data/models/"


def fmt(x):
    x = round(x, 1)
    return str(int(x)) if x == int(x) else f"{x:.1f}"


def obstacle_line(kind, x, z, heading=0, scale=None, model=None, color=None, radius=None):
    parts = [f'kind = "{kind}"']
    if model:
        parts.append(f'model = "{MODELS}{model}"')
    parts.append(f"position = [{fmt(x)}, 0, {fmt(z)}]")
    if heading:
        parts.append(f"heading = {fmt(heading)}")
    if scale and scale != 1:
        parts.append(f"scale = {fmt(scale)}")
    if radius:
        parts.append(f"radius = {fmt(radius)}")
    if color:
        parts.append(f'color = "{color}"')
    return "  { " + ", ".join(parts) + " },"


def camera_block(keys):
    out = []
    for t, eye, target in keys:
        out.append("[[camera_key]]")
        out.append(f"time = {fmt(t)}")
        out.append("eye = [" + ", ".join(fmt(c) for c in eye) + "]")
        out.append("target = [" + ", ".join(fmt(c) for c in target) + "]")
        out.append("")
    return "\n".join(out)


# Footprint radii of the shipped models at scale 1 (their bounds on the ground plane).
MODEL_RADIUS = {"pylon.obj": 6.1, "radar_dish.obj": 3.8, "ruined_tower.obj": 6.5, "tank_hulk.obj": 5.6}


def maze():
    rng = random.Random(1981)
    n, cell = 12, 20.0
    half = n * cell / 2
    # Depth-first carving gives a perfect maze; knocking out extra walls afterwards adds the
    # loops a tank fight needs (no dead end is safe).
    right = [[True] * n for _ in range(n)]  # wall on the +x side of cell (i, j)
    down = [[True] * n for _ in range(n)]   # wall on the +z side
    seen = [[False] * n for _ in range(n)]
    stack = [(n // 2, n // 2)]
    seen[n // 2][n // 2] = True
    while stack:
        i, j = stack[-1]
        options = [(di, dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
                   if 0 <= i + di < n and 0 <= j + dj < n and not seen[i + di][j + dj]]
        if not options:
            stack.pop()
            continue
        di, dj = rng.choice(options)
        if di == 1:
            right[i][j] = False
        elif di == -1:
            right[i - 1][j] = False
        elif dj == 1:
            down[i][j] = False
        else:
            down[i][j - 1] = False
        seen[i + di][j + dj] = True
        stack.append((i + di, j + dj))
    for _ in range(22):
        i, j = rng.randrange(n - 1), rng.randrange(n - 1)
        if rng.random() < 0.5:
            right[i][j] = False
        else:
            down[i][j] = False
    lines = []
    for i in range(n):
        for j in range(n):
            cx, cz = -half + cell * (i + 0.5), -half + cell * (j + 0.5)
            if i < n - 1 and right[i][j]:
                lines.append(obstacle_line("wall", cx + cell / 2, cz, heading=90))
            if j < n - 1 and down[i][j]:
                lines.append(obstacle_line("wall", cx, cz + cell / 2))
    # The outer wall, with the four corner cells' outside walls in a brighter colour.
    for k in range(n):
        c = -half + cell * (k + 0.5)
        lines.append(obstacle_line("wall", c, -half))
        lines.append(obstacle_line("wall", c, half))
        lines.append(obstacle_line("wall", -half, c, heading=90))
        lines.append(obstacle_line("wall", half, c, heading=90))
    # Pillars at a few crossings as landmarks.
    for i, j in ((3, 3), (3, 9), (9, 3), (9, 9)):
        lines.append(obstacle_line("tall_box", -half + cell * i, -half + cell * j, color="#ffcc33"))
    start = (-half + cell * (n // 2 + 0.5), -half + cell * (n // 2 + 0.5))
    body = f'''version = 1
# A dense walled maze, 12 x 12 cells of 20 units, with loops knocked through so no corridor
# is a safe dead end. Laid out by levels/generate.py (seeded); edit freely.
name = "The Maze"
author = "beamzone"
description = "Walls everywhere: hunt and be hunted through tight corridors. No wrap-around."

[field]
size = 280
wrap = false
obstacle_color = "#39ff88"

[player]
position = [{fmt(start[0])}, 0, {fmt(start[1])}]   # the centre of a cell near the middle
heading = 90                 # down the longest corridor from the start (48 units), not into a wall

[enemies]
types = ["slow_tank", "super_tank", "missile"]   # no saucer: it could not fly in here anyway
super_tank_score = 6000
missile_score = 3000
spawn_min_distance = 30
spawn_max_distance = 110
aggression = 0.65

[backdrop]
mountains = [[0, 6], [20, 9], [45, 5], [70, 10], [100, 7], [130, 11], [160, 6], [190, 9], [220, 5], [250, 10], [280, 7], [310, 11], [340, 6], [360, 6]]
volcano = false
moon = false

[render]
style = "occluded"           # hidden-line removal matters most where walls hide walls
preset = "balanced"
crease_angle = 40

obstacle = [
''' + "\n".join(lines) + "\n]\n\n"
    keys = [(0, (0, 90, 200), (0, 0, 0)), (6, (150, 60, 40), (0, 0, 0)), (12, (0, 40, -150), (0, 0, 0)),
            (18, (start[0], 2.5, start[1] + 8), (start[0], 2.5, start[1] - 60)),
            (24, (start[0], 2.5, start[1] - 2), (start[0] + 60, 2.5, start[1] - 2))]
    return body + camera_block(keys)


def scatter(rng, count, half, clear, taken, min_gap, region=None):
    """Up to `count` random points in the square (or `region`), at least `clear` from the
    origin and `min_gap` from every point in `taken`."""
    out = []
    tries = 0
    while len(out) < count and tries < count * 200:
        tries += 1
        if region:
            x0, x1, z0, z1 = region
            x, z = rng.uniform(x0, x1), rng.uniform(z0, z1)
        else:
            x, z = rng.uniform(-half, half), rng.uniform(-half, half)
        if math.hypot(x, z) < clear:
            continue
        if any(math.hypot(x - a, z - b) < min_gap for a, b in taken):
            continue
        taken.append((x, z))
        out.append((x, z))
    return out


def plains():
    rng = random.Random(1980)
    half = 950.0
    taken = []
    lines = []
    # A power line crossing the whole field diagonally: pylons every 70 units.
    for k in range(-13, 14):
        x, z = k * 70 * 0.8, k * 70 * 0.6 + 120
        if abs(x) > half or abs(z) > half:
            continue
        taken.append((x, z))
        lines.append(obstacle_line("model", x, z, heading=-36.87 + 90, model="pylon.obj",
                                   radius=MODEL_RADIUS["pylon.obj"], color="#8fd3ff"))
    # Clusters of blocks, like farmsteads, with open country between them.
    kinds = ["cube", "pyramid", "tall_box", "short_box"]
    for cx, cz in scatter(rng, 16, half - 60, 120, [], 220):
        for x, z in scatter(rng, rng.randint(5, 9), 0, 0, taken, 14, (cx - 45, cx + 45, cz - 45, cz + 45)):
            lines.append(obstacle_line(rng.choice(kinds), x, z, heading=rng.randrange(0, 90, 5)))
    # Battle remains and lonely ruins.
    for x, z in scatter(rng, 14, half, 60, taken, 40):
        lines.append(obstacle_line("model", x, z, heading=rng.randrange(0, 360, 15), model="tank_hulk.obj",
                                   radius=MODEL_RADIUS["tank_hulk.obj"], color="#b0ff60"))
    for x, z in scatter(rng, 6, half, 150, taken, 100):
        lines.append(obstacle_line("model", x, z, heading=rng.randrange(0, 360, 15), model="ruined_tower.obj",
                                   radius=MODEL_RADIUS["ruined_tower.obj"], scale=1.3))
    # A radar station on a rise of the ground ahead of the start.
    for x, z in ((0, -260), (30, -285), (-30, -285)):
        taken.append((x, z))
        lines.append(obstacle_line("model", x, z, heading=rng.randrange(0, 360, 30), model="radar_dish.obj",
                                   radius=MODEL_RADIUS["radar_dish.obj"], color="#ffdd55"))
    # Lone markers so the radar is never empty.
    for x, z in scatter(rng, 30, half, 40, taken, 50):
        lines.append(obstacle_line(rng.choice(kinds), x, z, heading=rng.randrange(0, 90, 5)))
    body = f'''version = 1
# A large open field: {len(lines)} objects spread over 1900 x 1900 units. Farmsteads of blocks,
# a power line of pylons, wrecks, ruins and a radar station. Laid out by levels/generate.py
# (seeded); edit freely.
name = "Open Plains"
author = "beamzone"
description = "Wide open country with farmsteads, a power line and a radar station. Long sight lines, long drives."

[field]
size = 1900
wrap = true

[player]
position = [0, 0, 0]
heading = 0                  # the radar station is straight ahead

[enemies]
types = ["slow_tank", "super_tank", "missile", "saucer"]
super_tank_score = 8000
missile_score = 4000
spawn_min_distance = 70
spawn_max_distance = 260
aggression = 0.55

[backdrop]
mountains = [[0, 0.8], [30, 1.6], [60, 0.9], [95, 2.2], [120, 1.2], [150, 0.7], [185, 1.9], [215, 1.1], [250, 2.6], [280, 1.4], [320, 0.9], [360, 0.8]]
volcano = true
volcano_azimuth = 250
moon = true
moon_azimuth = 120
moon_elevation = 30

[render]
preset = "balanced"

obstacle = [
''' + "\n".join(lines) + "\n]\n\n"
    keys = []
    # Along the power line, then a long arc round the radar station.
    for k in range(0, 9):
        t = k * 4
        s = -700 + k * 150
        keys.append((t, (s * 0.8 + 40, 12, s * 0.6 + 120 - 30), (s * 0.8 + 160, 6, s * 0.6 + 210 - 30)))
    for k in range(1, 7):
        a = k * math.pi / 6
        keys.append((32 + k * 4, (200 * math.sin(a), 25, -260 + 200 * math.cos(a)), (0, 5, -260)))
    return body + camera_block(keys)


def stress():
    rng = random.Random(2024)
    half = 590.0
    lines = []
    taken = []
    kinds = ["cube", "pyramid", "tall_box", "short_box", "wall"]
    colors = ["#33ff66", "#66ffcc", "#ccff33", "#ff6633", "#33ccff"]
    # A jittered grid fills the field evenly so every view of the path has plenty in it.
    step = 48.0
    k = int(half // step)
    for i in range(-k, k + 1):
        for j in range(-k, k + 1):
            x = i * step + rng.uniform(-9, 9)
            z = j * step + rng.uniform(-9, 9)
            if math.hypot(x, z) < 30:
                continue
            taken.append((x, z))
            roll = rng.random()
            if roll < 0.16:
                model = rng.choice(["radar_dish.obj", "tank_hulk.obj", "ruined_tower.obj", "pylon.obj"])
                lines.append(obstacle_line("model", x, z, heading=rng.randrange(0, 360, 5), model=model,
                                           radius=MODEL_RADIUS[model], color=rng.choice(colors)))
            else:
                kind = rng.choice(kinds)
                scale = rng.choice([0.8, 1, 1, 1.2, 1.5]) if kind != "wall" else 1
                lines.append(obstacle_line(kind, x, z, heading=rng.randrange(0, 180, 5), scale=scale,
                                           color=rng.choice(colors)))
    body = f'''version = 1
# The benchmark stress level: {len(lines)} objects, about a sixth of them imported models
# from data/models, on a 1180-unit field, with a 60 s camera path that weaves through the
# thickest of it. No enemies, so every run draws the same frames. Laid out by
# levels/generate.py (seeded); edit freely.
name = "Stress Test"
author = "beamzone"
description = "Benchmark: hundreds of objects and imported models along a fixed 60 s camera path."
listed = false      # a benchmark scene, not a game: kept out of the level menu

[field]
size = 1180
wrap = true

[player]
position = [0, 0, 0]

[enemies]
types = []                   # a benchmark wants the same frames every run

[backdrop]
volcano = true
volcano_azimuth = 30
moon = true
moon_azimuth = 200
moon_elevation = 22

[render]
preset = "high"

obstacle = [
''' + "\n".join(lines) + "\n]\n\n"
    keys = []
    # Low over the ground along a Lissajous curve, always looking a little ahead.
    for n in range(0, 31):
        t = n * 2.0
        a = 2 * math.pi * t / 60
        eye = (420 * math.sin(a), 9 + 6 * math.sin(3 * a), 420 * math.sin(2 * a))
        b = a + 0.12
        target = (420 * math.sin(b), 4, 420 * math.sin(2 * b))
        keys.append((t, eye, target))
    return body + camera_block(keys)


def hoist_obstacles(text):
    """TOML files every key after a [table] header into that table, so the top-level obstacle
    list has to come before [field]; the templates above read better with it at the end."""
    start = text.index("obstacle = [\n")
    end = text.index("\n]\n", start) + 3
    block = text[start:end]
    text = text[:start] + text[end:]
    first_table = text.index("\n[field]")
    note = "\n# The obstacles, one per line; the settings tables follow the list.\n"
    return text[:first_table] + note + block + text[first_table:]


def main():
    for name, make in (("maze.toml", maze), ("plains.toml", plains), ("stress.toml", stress)):
        text = hoist_obstacles(make())
        with open(os.path.join(HERE, name), "w") as out:
            out.write(text)
        print(f"{name}: {text.count('kind = ')} obstacles, {len(text)} bytes")


if __name__ == "__main__":
    main()
