#!/usr/bin/env python3
"""Compare two pound HDF5 files dataset by dataset, bit for bit.

    scripts/h5_compare A.h5 B.h5 [--ignore-attr NAME ...] [--rtol R] [--transposed PREFIX ...]

Every group, dataset and attribute of either file must exist in the other with the same
shape, type and bytes (NaN compares equal to NaN at the same place). Attributes that carry
the run's date or wall-clock timings (names ending in "seconds") are ignored. Exit 0 when identical, 1 with one line per
difference otherwise, 2 on a usage error or an unreadable file.

With --rtol R, floating-point datasets whose bytes differ are compared numerically instead:
they pass when max |a - b| <= R max |a| over the dataset (the largest relative difference of
every such dataset is printed, to document round-off differences); attributes stay exact.

With --transposed PREFIX, a 2-D dataset of A whose path starts with PREFIX (no leading '/') is
compared transposed with B's: for comparing files across a change of a dataset's orientation
(issue 27 stored /suite/spectrum/sa, /suite/influence, /suite/separation, /suite/sweep/max_abs_lambda
and /suite/sweep/failed with one row per motion; an older file has them transposed).
"""
import sys

import h5py
import numpy as np

DEFAULT_IGNORED = {"date", "created"}
# Wall-clock timings differ between runs by nature.
TIMING_SUFFIX = "seconds"


def walk(f):
    out = {}

    def visit(name, obj):
        out[name] = obj

    f.visititems(visit)
    out["/"] = f
    return out


def same(a, b):
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind in "fc":
        return a.tobytes() == b.tobytes()
    return bool(np.array_equal(a, b))


def relative_difference(a, b):
    """max |a - b| / max |a| of two floating-point arrays of one shape (None otherwise)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype.kind != "f" or b.dtype.kind != "f":
        return None
    if not np.array_equal(np.isnan(a), np.isnan(b)):
        return None
    ok = ~np.isnan(a)
    scale = np.max(np.abs(a[ok]), initial=0.0)
    diff = np.max(np.abs(a[ok] - b[ok]), initial=0.0)
    return float(diff / scale) if scale > 0 else (0.0 if diff == 0 else float("inf"))


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    ignored = set(DEFAULT_IGNORED)
    rtol = None
    transposed = []
    while "--transposed" in argv:
        i = argv.index("--transposed")
        if i + 1 >= len(argv):
            print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
            return 2
        transposed.append(argv[i + 1].lstrip("/"))
        argv = argv[:i] + argv[i + 2:]
    args = [a for a in argv if not a.startswith("--")]
    if "--rtol" in argv:
        i = argv.index("--rtol")
        if i + 1 >= len(argv):
            print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
            return 2
        rtol = float(argv[i + 1])
        args.remove(argv[i + 1])
    for i, a in enumerate(argv):
        if a == "--ignore-attr" and i + 1 < len(argv):
            ignored.add(argv[i + 1])
            args.remove(argv[i + 1])
    if len(args) != 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    try:
        fa, fb = h5py.File(args[0], "r"), h5py.File(args[1], "r")
    except OSError as e:
        print(f"h5_compare: error: {e}", file=sys.stderr)
        return 2
    ia, ib = walk(fa), walk(fb)
    diffs = []
    for name in sorted(set(ia) | set(ib)):
        if name not in ia or name not in ib:
            diffs.append(f"{name}: only in {args[0] if name in ia else args[1]}")
            continue
        oa, ob = ia[name], ib[name]
        if isinstance(oa, h5py.Dataset) != isinstance(ob, h5py.Dataset):
            diffs.append(f"{name}: group in one file, dataset in the other")
            continue
        va = oa[()] if isinstance(oa, h5py.Dataset) else None
        if va is not None and va.ndim == 2 and any(name.startswith(p) for p in transposed):
            va = va.T
        if isinstance(oa, h5py.Dataset) and not same(va, ob[()]):
            rel = relative_difference(va, ob[()]) if rtol is not None else None
            if rel is None or rel > rtol:
                diffs.append(f"{name}: data differ" + ("" if rel is None else f" (relative {rel:.3e})"))
            else:
                print(f"{name}: relative difference {rel:.3e} <= {rtol:g}")
        for k in sorted(set(oa.attrs) | set(ob.attrs)):
            if k in ignored or k.endswith(TIMING_SUFFIX):
                continue
            if k not in oa.attrs or k not in ob.attrs:
                diffs.append(f"{name}@{k}: attribute in one file only")
            elif not same(oa.attrs[k], ob.attrs[k]):
                diffs.append(f"{name}@{k}: attribute differs")
    for d in diffs:
        print(d)
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
