#!/usr/bin/env python3
"""Writes shaders/wb/poisson.glsl: 64 points in the unit disk by best-candidate (Mitchell) sampling,
so that every prefix (16, 32, 64) is itself well spread. A fixed LCG makes it reproducible:
    /usr/bin/python3 tools/make_poisson_disk.py > shaders/wb/poisson.glsl
"""
import math

state = 12345


def rnd():
    global state
    state = (1103515245 * state + 12345) % (1 << 31)
    return state / (1 << 31)


points = []
while len(points) < 64:
    best, best_distance = None, -1.0
    for _ in range(30 * (len(points) + 1) if len(points) < 8 else 200):
        r, a = math.sqrt(rnd()), 2 * math.pi * rnd()
        p = (r * math.cos(a), r * math.sin(a))
        d = min((math.dist(p, q) for q in points), default=1e9)
        if d > best_distance:
            best, best_distance = p, d
    points.append(best)

print("// Generated once by best-candidate sampling in the unit disk (any prefix is well spread, so the")
print("// first 16 and 32 points are the smaller kernels). Used by lab 03's Poisson-disk PCF.")
print("#ifndef WB_POISSON_GLSL")
print("#define WB_POISSON_GLSL")
print("const vec2 WB_POISSON_DISK[64] = vec2[](")
print(",\n".join("    vec2(%.6f, %.6f)" % p for p in points) + ");")
print("#endif")
