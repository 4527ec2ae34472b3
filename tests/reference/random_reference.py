#!/usr/bin/env python3
"""Independent reference for src/core/pound_random.f90 (run once; its output is pasted into
tests/test_random.pf). Python integers, masked to 64 bits: splitmix64 seeding, xoshiro256**,
u = ((x >> 12) + 0.5) * 2**-52, Marsaglia's polar method for normals."""
import math
import sys

M64 = (1 << 64) - 1


def splitmix64(state):
    state = (state + 0x9E3779B97F4A7C15) & M64
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M64
    return state, z ^ (z >> 31)


def rotl(x, k):
    return ((x << k) | (x >> (64 - k))) & M64


class Xoshiro:
    def __init__(self, seed):
        sm = seed & M64
        self.s = []
        for _ in range(4):
            sm, x = splitmix64(sm)
            self.s.append(x)
        self.spare = None

    def next(self):
        s = self.s
        result = (rotl((s[1] * 5) & M64, 7) * 9) & M64
        t = (s[1] << 17) & M64
        s[2] ^= s[0]
        s[3] ^= s[1]
        s[1] ^= s[2]
        s[0] ^= s[3]
        s[2] ^= t
        s[3] = rotl(s[3], 45)
        return result

    def uniform(self):
        return ((self.next() >> 12) + 0.5) * 2.0**-52

    def normal(self):
        if self.spare is not None:
            z, self.spare = self.spare, None
            return z
        while True:
            v1 = 2.0 * self.uniform() - 1.0
            v2 = 2.0 * self.uniform() - 1.0
            s = v1 * v1 + v2 * v2
            if 0.0 < s < 1.0:
                break
        f = math.sqrt(-2.0 * math.log(s) / s)
        self.spare = v2 * f
        return v1 * f


def signed(x):
    return x - (1 << 64) if x >> 63 else x


if __name__ == "__main__":
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 42
    sm, out = 0, []
    for _ in range(3):
        sm, x = splitmix64(sm)
        out.append(x)
    print("splitmix64 from 0:", [hex(x) for x in out])
    g = Xoshiro(seed)
    print("state", [signed(x) for x in g.s])
    print("words", [signed(g.next()) for _ in range(5)])
    g = Xoshiro(seed)
    print("uniform", [repr(g.uniform()) for _ in range(5)])
    g = Xoshiro(seed)
    print("normal", [repr(g.normal()) for _ in range(6)])
