"""Generated scenes for the truth suite: simple casters over a ground slab, drawn from a fixed-seed
random generator, so that no single hand-placed scene can be tuned for.

Each scene has one light (directional, spot with a size, or point) and two camera bookmarks: 1 looks
down on the casters from outside every shadow volume; 2 puts the eye inside the shadow volume of a
floating caster (just behind it, away from the light), the case only z-fail gets right.
"""
import json
import math
import random

GROUND = {"name": "ground", "shape": "box", "size": [14, 0.2, 14], "position": [0, -0.1, 0],
          "color": [0.72, 0.7, 0.66], "casts_volume": False}


def _norm(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def _caster(rng, kind, x, z, top):
    """One caster at (x, z): a floating sphere, a box resting on the ground or floating, or a thin
    tilted disk. Its highest point stays below `top`. Returns (object, centre, radius)."""
    if kind == "sphere":
        r = rng.uniform(0.3, 0.6)
        y = rng.uniform(r + 0.25, min(top - r, 1.9))
        return {"shape": "sphere", "radius": round(r, 3), "position": [x, round(y, 3), z]}, [x, y, z], r
    if kind == "box":
        s = [rng.uniform(0.4, 1.0), rng.uniform(0.4, 1.0), rng.uniform(0.4, 1.0)]
        lift = 0.0 if rng.random() < 0.5 else rng.uniform(0.3, 0.8)  # resting, or floating
        lift = min(lift, max(0.0, top - s[1] - 0.05))
        y = s[1] / 2 + lift
        obj = {"shape": "box", "size": [round(c, 3) for c in s], "position": [x, round(y, 3), z],
               "rotation": [0, round(rng.uniform(0, 90), 1), 0]}
        return obj, [x, y, z], 0.5 * math.sqrt(sum(c * c for c in s))
    r = rng.uniform(0.35, 0.7)  # a thin disk: a cylinder 4 cm tall, tilted
    y = rng.uniform(0.6, min(top - r, 1.8))
    obj = {"shape": "cylinder", "radius": round(r, 3), "height": 0.04, "position": [x, round(y, 3), z],
           "rotation": [round(rng.uniform(-35, 35), 1), 0, round(rng.uniform(-35, 35), 1)]}
    return obj, [x, y + 0.02, z], r


def _light(rng, light_type):
    if light_type == "directional":
        elevation, azimuth = math.radians(rng.uniform(40, 70)), rng.uniform(0, 2 * math.pi)
        d = [math.cos(elevation) * math.cos(azimuth), -math.sin(elevation), math.cos(elevation) * math.sin(azimuth)]
        return {"type": "directional", "direction": [round(c, 4) for c in d], "color": [1, 1, 1]}
    if light_type == "spot":
        azimuth, reach = rng.uniform(0, 2 * math.pi), rng.uniform(1.0, 3.0)
        p = [reach * math.cos(azimuth), rng.uniform(6.5, 8.5), reach * math.sin(azimuth)]
        d = _norm([-p[0], -p[1], -p[2]])
        return {"type": "spot", "position": [round(c, 3) for c in p], "direction": [round(c, 4) for c in d],
                "angle": 40, "near": 2.0, "far": 20, "size": round(rng.uniform(0.3, 0.6), 2), "color": [1, 1, 1]}
    p = [rng.uniform(-0.8, 0.8), rng.uniform(2.8, 3.6), rng.uniform(-0.8, 0.8)]
    return {"type": "point", "position": [round(c, 3) for c in p], "near": 0.05, "far": 20, "color": [1, 1, 1]}


def _inside_bookmark(light, centre, radius):
    """A bookmark whose eye is in the shadow volume of the caster at `centre`: a little past the
    caster, away from the light, looking down across the ground."""
    if light["type"] == "directional":
        away = _norm(light["direction"])
    else:
        away = _norm([c - p for c, p in zip(centre, light["position"])])
    eye = [c + a * (radius + 0.12) for c, a in zip(centre, away)]
    eye[1] = max(eye[1], 0.15)
    yaw, pitch, distance = math.atan2(away[0], away[2]) + math.pi, math.radians(35), 4.0
    back = [math.sin(yaw) * math.cos(pitch), math.sin(pitch), math.cos(yaw) * math.cos(pitch)]
    target = [e - b * distance for e, b in zip(eye, back)]
    return {"name": "inside a volume", "target": [round(c, 4) for c in target], "distance": distance,
            "yaw": round(math.degrees(yaw), 3), "pitch": 35, "fov": 60}, eye


def generate(light_type, seed):
    """A scene dictionary (the workbook's scene format) and the eye of its inside-volume bookmark."""
    rng = random.Random(f"{light_type}-{seed}")
    light = _light(rng, light_type)
    top = light["position"][1] - 0.9 if light_type == "point" else 2.4
    objects, spots = [dict(GROUND)], []
    kinds = ["sphere", "box", "disk", rng.choice(["sphere", "box", "disk"])]
    floating = None
    for n, kind in enumerate(kinds):
        for _ in range(100):  # a place clear of the others (and, for a point light, of the light)
            x, z = round(rng.uniform(-2.6, 2.6), 3), round(rng.uniform(-2.6, 2.6), 3)
            if all(math.hypot(x - a, z - b) > 1.7 for a, b in spots):
                break
        spots.append((x, z))
        obj, centre, radius = _caster(rng, kind, x, z, top)
        obj.update(name=f"{kind} {n + 1}", color=[0.8, 0.45, 0.3])
        objects.append(obj)
        if floating is None and kind in ("sphere", "disk"):
            floating = (centre, radius)
    yaw = round(rng.uniform(0, 360), 1)
    inside, eye = _inside_bookmark(light, *floating)
    scene = {"comment": f"truth suite: {light_type} scene {seed} (tools/truth/scenes.py)", "objects": objects,
             "lights": [light],
             "cameras": [{"name": "overview", "target": [0, 0.3, 0], "distance": 10.5, "yaw": yaw, "pitch": 52,
                          "fov": 50}, inside]}
    return scene, eye


def write(path, light_type, seed):
    scene, _ = generate(light_type, seed)
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
