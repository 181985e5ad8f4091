#!/usr/bin/python3
"""Checks nastran-summary's output for the decks of scripts/make-nastran-wingbox (docs/nastran.md).

    check_nastran_wingbox.py MANIFEST SUMMARY       the summary against the generator's manifest
    check_nastran_wingbox.py --same SUMMARY...      summaries of the three formats agree

The manifest is computed by the generator, independently of the reader: card counts and the
bounding box must match (box to 1e-9 relative), and per subcase the constrained dof exactly and the
load resultant to 1e-9 of its magnitude (round-off of the transforms and the pressure integrals).
"""
import json
import re
import sys


def parse(path):
    text = open(path).read()
    s = {"used": {}, "unused": {}, "subcases": {}}
    section = None
    for line in text.splitlines():
        m = re.match(r"^cards used: (\d+)$", line)
        if m:
            section = "used"
            continue
        if line.startswith("cards not used:"):
            section = "unused"
            continue
        if not line.startswith("  "):
            section = None
        m = re.match(r"^  ([A-Z0-9]+) (\d+)", line)
        if m and section in ("used", "unused"):
            s[section][m.group(1)] = int(m.group(2))
        m = re.match(r"^bounding box: x \[(\S+), (\S+)\] y \[(\S+), (\S+)\] z \[(\S+), (\S+)\]$", line)
        if m:
            v = [float(x) for x in m.groups()]
            s["box"] = [[v[0], v[2], v[4]], [v[1], v[3], v[5]]]
        m = re.match(r"^model: (\d+) grids", line)
        if m:
            s["grids"] = int(m.group(1))
        m = re.match(r"^  subcase (\d+).*: SPC \d+ \((\d+) grids, (\d+) dof\)", line)
        if m:
            current = s["subcases"][m.group(1)] = {"spc_grids": int(m.group(2)), "spc_dof": int(m.group(3))}
        m = re.match(r"^    force \[(.*)\] moment about the origin \[(.*)\]$", line)
        if m:
            current["force"] = [float(x) for x in m.group(1).split(",")]
            current["moment"] = [float(x) for x in m.group(2).split(",")]
    return s, text


def close(got, want, scale, rtol):
    return all(abs(g - w) <= rtol * scale for g, w in zip(got, want))


def check(manifest, summary):
    want = json.load(open(manifest))
    got, text = parse(summary)
    bad = []
    if got["used"] != want["cards_used"]:
        bad.append("cards used %s, expected %s" % (got["used"], want["cards_used"]))
    if got["unused"] != want["cards_not_used"]:
        bad.append("cards not used %s, expected %s" % (got["unused"], want["cards_not_used"]))
    if got.get("grids") != want["grids"]:
        bad.append("grids %s, expected %s" % (got.get("grids"), want["grids"]))
    box, wbox = got.get("box"), want["bounding_box"]
    size = max(abs(x) for x in wbox[0] + wbox[1])
    if not box or not (close(box[0], wbox[0], size, 1e-9) and close(box[1], wbox[1], size, 1e-9)):
        bad.append("bounding box %s, expected %s" % (box, wbox))
    for sid, w in want["subcases"].items():
        g = got["subcases"].get(sid)
        if not g:
            bad.append("subcase %s missing" % sid)
            continue
        for key in ("spc_grids", "spc_dof"):
            if g[key] != w[key]:
                bad.append("subcase %s %s %s, expected %s" % (sid, key, g[key], w[key]))
        for key in ("force", "moment"):
            scale = max(abs(x) for x in w[key])
            if not close(g[key], w[key], scale, 1e-9):
                bad.append("subcase %s %s %s, expected %s" % (sid, key, g[key], w[key]))
    if bad:
        print(text)
        print("\n".join("MISMATCH: " + b for b in bad))
        return 1
    print("%s: %d cards, box, %d subcases match %s" % (summary, sum(got["used"].values()), len(want["subcases"]), manifest))
    return 0


def same(paths):
    # The summaries differ only in file names and the lines where cards start.
    norm = []
    for p in paths:
        t = open(p).read()
        t = re.sub(r"\S*wingbox-(small|large|free)", "wingbox", t)
        t = re.sub(r" \(first at [^)]*\)", "", t)
        norm.append(t)
    for p, t in zip(paths[1:], norm[1:]):
        if t != norm[0]:
            print("%s and %s differ:\n%s\n---\n%s" % (paths[0], p, norm[0], t))
            return 1
    print("the %d summaries agree" % len(paths))
    return 0


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "--same":
        sys.exit(same(sys.argv[2:]))
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(check(sys.argv[1], sys.argv[2]))
