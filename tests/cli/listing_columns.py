#!/usr/bin/python3
"""Check a pound listing's tables and its results file (issue 27, tests/cli/listing_columns.cmake).

    listing_columns.py LISTING.out RESULTS.h5 MIN_TABLES [N_MOTIONS]

Tables: a heading line (column names separated by at least two blanks, no word of it a number)
followed directly by rows (lines with at least two numbers making at least a third of the
cells before a free-text 'message' column, whose first cell is a number when
the first row's is, a name when the first row's is). Every row up to the next blank or
non-row line must split at blanks into exactly as many cells as the heading has names (a row
saying FAILED and the free-text 'message' column excepted), and every cell made of digits,
signs, points and exponents must be one number (no '31.0381682545.9'). At least MIN_TABLES
tables must be found. Results: every dataset has a non-empty string attribute 'units'; with
N_MOTIONS, the per-motion /suite arrays have one row per motion.
Exit 0 when all holds; 1 with one line per failure.
"""
import re
import sys

import h5py

def number(t):
    try:
        float(t)
        return True
    except ValueError:
        return False


def is_row(line, names):
    """At least two numbers, and at least a third of the cells (before a free-text 'message')."""
    cells = line.split()
    if names[-1] == "message":
        cells = cells[:len(names) - 1]
    n = sum(number(t) for t in cells)
    return n >= 2 and 3 * n >= len(cells)


def heading(line):
    names = re.split(r" {2,}", line.strip())
    if len(names) < 2 or any(number(t) for t in line.split()) or "FAILED" in line.split():
        return None
    return names


def check_listing(path, min_tables):
    lines = open(path, encoding="utf-8").read().split("\n")
    problems, tables, rows = [], 0, 0
    for i, line in enumerate(lines[:-1]):
        names = heading(line)
        if names is None or not is_row(lines[i + 1], names) or line.startswith("  |"):
            continue
        tables += 1
        free_text = names[-1] == "message"
        numbered = number(lines[i + 1].split()[0])
        for j in range(i + 1, len(lines)):
            row = lines[j]
            if row.strip() and "FAILED" in row.split():
                continue
            if not row.strip() or not is_row(row, names) or number(row.split()[0]) != numbered:
                break
            cells = row.split()
            rows += 1
            for c in cells:
                if re.fullmatch(r"[-+0-9.eE]*[0-9][-+0-9.eE]*", c) and not number(c):
                    problems.append(f"{path}:{j + 1}: cell '{c}' is not one number: {row.strip()}")
            if len(cells) != len(names) and not (free_text and len(cells) >= len(names)):
                problems.append(f"{path}:{j + 1}: {len(cells)} cells under {len(names)} headings "
                                f"{names}: {row.strip()}")
    if tables < min_tables:
        problems.append(f"{path}: only {tables} tables found (expected at least {min_tables})")
    print(f"{path}: {tables} tables, {rows} rows checked")
    return problems


def check_results(path, n_motions):
    problems = []
    f = h5py.File(path, "r")
    count = [0]

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            count[0] += 1
            u = obj.attrs.get("units")
            if not isinstance(u, str) or not u:
                problems.append(f"{path}: /{name} has no 'units' attribute")

    f.visititems(visit)
    print(f"{path}: {count[0]} datasets checked for 'units'")
    if n_motions is not None:
        s = f["suite"]
        names = s["names"].asstr()[...]
        if len(names) != n_motions:
            problems.append(f"{path}: /suite/names {list(names)}")
        per_motion = ["spectrum/sa", "sweep/max_abs_lambda"]
        # every dataset under /suite/influence (a frame's column segments in influence/<b>/columns)
        s["influence"].visititems(lambda name, obj: per_motion.append(f"influence/{name}")
                                  if isinstance(obj, h5py.Dataset) else None)
        for name in per_motion:
            if s[name].shape[0] != n_motions:
                problems.append(f"{path}: /suite/{name} has shape {s[name].shape}: not one row per motion")
        for name in s["separation"]:
            if s["separation"][name].dtype.kind not in "fiu" or name == "mean_closing":
                continue  # the pair labels, the mean closing displacement (one per pair)
            if s["separation"][name].shape[0] != n_motions + 1:
                problems.append(f"{path}: /suite/separation/{name} has shape {s['separation'][name].shape}")
    return problems


def main(argv):
    listing, results, min_tables = argv[0], argv[1], int(argv[2])
    n_motions = int(argv[3]) if len(argv) > 3 else None
    problems = check_listing(listing, min_tables) + check_results(results, n_motions)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
