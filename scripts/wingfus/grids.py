"""Piecewise-uniform 1D grids: the node lines every part of the junction is built on.

A grid is a list of segments (a, b, n): n equal elements from a to b. Parts that are fastened
together use grids whose element centres coincide where the fasteners are (the same grid, or one
whose spacing is an odd multiple of the other's, aligned at a common node), so that every fastener
sits at the centre of an element of both parts it joins.
"""
import math

import numpy as np


class Grid:
    def __init__(self, segments=()):
        self.segs = []
        for a, b, n in segments:
            self.add(a, b, n)

    def add(self, a, b, n):
        n = int(n)
        if n < 1 or not b > a:
            raise ValueError(f"bad grid segment [{a}, {b}] with {n} elements")
        if self.segs and abs(self.segs[-1][1] - a) > 1e-9 * max(1.0, abs(a)):
            raise ValueError(f"grid segment [{a}, {b}] does not start where [{self.segs[-1][0]}, {self.segs[-1][1]}] ends")
        self.segs.append((float(a), float(b), n))
        return self

    def add_size(self, a, b, h):
        """A segment with elements of about h (at least one)."""
        return self.add(a, b, max(1, round((b - a) / h)))

    @property
    def start(self):
        return self.segs[0][0]

    @property
    def end(self):
        return self.segs[-1][1]

    def nodes(self):
        out = [self.segs[0][0]]
        for a, b, n in self.segs:
            out.extend(a + (b - a) * i / n for i in range(1, n + 1))
        return np.array(out)

    def nelem(self):
        return sum(n for _, _, n in self.segs)

    def centres(self, a=None, b=None):
        """Element centres (optionally only those inside [a, b])."""
        x = self.nodes()
        c = 0.5 * (x[1:] + x[:-1])
        if a is not None:
            c = c[(c > a) & (c < b)]
        return c

    def mirrored(self):
        """The grid of -x (for the left side of the aircraft)."""
        return Grid([(-b, -a, n) for a, b, n in reversed(self.segs)])

    def __add__(self, other):
        g = Grid(self.segs)
        for s in other.segs:
            g.add(*s)
        return g


def uniform_count(length, h):
    return max(1, int(round(length / h)))


def round_up_to(n, m):
    return int(math.ceil(n / m) * m)
