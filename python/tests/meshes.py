"""Meshes as NumPy arrays whose counts are known in closed form, for the tests and python/bench."""

import numpy as np


def torus_arrays(n, m, major=2.0, minor=0.5):
    """An n x m grid of quads wrapped both ways onto a torus: V = nm, E = 2nm, F = nm, genus 1. Vertex
    (i, j) is i * m + j; face (i, j) is (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1), counter-clockwise
    seen from outside, as bench/bench_meshes.h builds it."""
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    u, v = 2 * np.pi * i / n, 2 * np.pi * j / m
    positions = np.stack(
        [(major + minor * np.cos(v)) * np.cos(u), (major + minor * np.cos(v)) * np.sin(u), minor * np.sin(v)],
        axis=-1,
    ).reshape(-1, 3)

    def vid(a, b):
        return (a % n) * m + (b % m)

    faces = np.stack([vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)], axis=-1).reshape(-1, 4)
    return positions, faces


def grid_arrays(n, m):
    """An open n x m grid of unit quads in the plane z = 0: V = (n+1)(m+1), F = nm, one boundary loop."""
    i, j = np.meshgrid(np.arange(n + 1), np.arange(m + 1), indexing="ij")
    positions = np.stack([i, j, np.zeros_like(i)], axis=-1).reshape(-1, 3).astype(float)
    a, b = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")

    def vid(x, y):
        return x * (m + 1) + y

    faces = np.stack([vid(a, b), vid(a + 1, b), vid(a + 1, b + 1), vid(a, b + 1)], axis=-1).reshape(-1, 4)
    return positions, faces


CUBE_POSITIONS = [[-1, -1, -1], [1, -1, -1], [-1, 1, -1], [1, 1, -1], [-1, -1, 1], [1, -1, 1], [-1, 1, 1], [1, 1, 1]]
CUBE_FACES = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def prism_rows_arrays(n, rows, height=3.0):
    """The n-gonal prism of radius 1 and the given height with each side split into `rows` quads (a convex
    shape with flat sides, docs/lateral_artifacts.md): V = n (rows + 1), E = n (2 rows + 1), F = n rows + 2."""
    a = 2 * np.pi * np.arange(n) / n
    positions = np.array([[np.cos(t), np.sin(t), height * z / rows] for z in range(rows + 1) for t in a])

    def vid(z, i):
        return z * n + i % n

    faces = [[vid(0, i) for i in reversed(range(n))], [vid(rows, i) for i in range(n)]]
    faces += [[vid(z, i), vid(z, i + 1), vid(z + 1, i + 1), vid(z + 1, i)] for z in range(rows) for i in range(n)]
    return positions, faces
