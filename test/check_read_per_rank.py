#!/usr/bin/python3
"""Checks that each shell part is read and laid out by one rank only (lib/patch/layout.cpp), and
that past the set-up each rank keeps the components of its own joints only (lib/network/build.cpp).

  check_read_per_rank.py SCENE.yaml RANKS INFO -- COMMAND...

Runs COMMAND (an mpirun of the driver with -info INFO, which writes each rank's lines to its own
file INFO.r: info_files.py) and reads each rank's lines

  [r] LayoutCreate(): Read and laid out K of P shell parts (n of N mesh nodes) on this rank
  [r] ReleaseUnowned(): Kept the meshes of m of M shell patches (k nodes) on this rank past the set-up
  [r] ReleaseUnowned(): Kept the components of j of J joints on this rank past the set-up
  [r] SceneDescribeAssemblyImpl(): Read the fastener table's J rows on this rank
  [r] ShareJoints(): Attaching a of J joints (s joint sides) on this rank's shell parts

The reference is the scene's own tables, read here: P must be the patches table's number of shell
rows (plate or gmsh), N the nodes of those parts (a plate's (nx + 1) (ny + 1); a Gmsh part's nodes,
counted in its file by its physical surface's elements), J the joints table's rows, S their sides on
shell parts (a joint between two shell parts has two, one to a rigid part one). Over the ranks the K
must add up to P, the n to N, the j to J and the s to S (every part read once, every joint kept once,
every side attached once), and with several ranks no rank may read every part or keep every joint.
Past the set-up each shell patch's mesh is kept by the one rank that owns it (its network vertex):
the m add up to M, so that no rank holds a patch of another, even one its joints attach to.
Only rank 0 may read the fastener table, and each joint with a side on a shell part is sent to the
holders of its parts only: once or twice, so that the ranks are sent between JS (the joints with a
side on a shell part) and S joints in all.
"""
import csv
import os
import re
import sys

import info_files


def gmsh_part_nodes(path, part):
    """The nodes of the elements of physical surface `part` in an MSH 4.1 ASCII file."""
    lines = open(path).read().split("\n")
    i, names, surf_phys, nodes = 0, {}, {}, set()
    while i < len(lines):
        s = lines[i].strip()
        if s == "$PhysicalNames":
            n = int(lines[i + 1])
            for k in range(n):
                w = lines[i + 2 + k].split(maxsplit=2)
                if int(w[0]) == 2:
                    names[w[2].strip('"')] = int(w[1])
            i += n + 2
        elif s == "$Entities":
            npts, ncur, nsrf, _ = map(int, lines[i + 1].split())
            for k in range(nsrf):
                w = lines[i + 2 + npts + ncur + k].split()
                tag, nphys = int(w[0]), int(w[7])
                surf_phys[tag] = [int(x) for x in w[8:8 + nphys]]
            i += 2
        elif s == "$Elements":
            nblocks = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(nblocks):
                dim, tag, typ, n = map(int, lines[j].split())
                keep = dim == 2 and names.get(part) in surf_phys.get(tag, [])
                for k in range(n):
                    if keep:
                        nodes.update(int(x) for x in lines[j + 1 + k].split()[1:])
                j += n + 1
            i = j
        else:
            i += 1
    return len(nodes)


def scene_parts(scene):
    """(shell parts, their nodes) from the scene's patches table."""
    text = open(scene).read()
    m = re.search(r"^\s*patches:\s*(\S+)", text, re.M)
    table = os.path.join(os.path.dirname(scene), m.group(1))
    parts = nodes = 0
    for row in csv.DictReader(line for line in open(table) if not line.startswith("#")):
        kind = row["kind"].strip()
        if kind == "plate":
            nodes += (int(row["nx"]) + 1) * (int(row["ny"]) + 1)
        elif kind == "gmsh":
            nodes += gmsh_part_nodes(os.path.join(os.path.dirname(table), row["mesh"].strip()), row["part"].strip())
        else:
            continue
        parts += 1
    return parts, nodes


def table_rows(scene, key):
    """The rows of the scene's table named by `key` (patches, joints)."""
    text = open(scene).read()
    m = re.search(r"^\s*" + key + r":\s*(\S+)", text, re.M)
    table = os.path.join(os.path.dirname(scene), m.group(1))
    return list(csv.DictReader(line for line in open(table) if not line.startswith("#")))


def scene_joints(scene):
    """The rows of the scene's joints table, and their sides on shell parts."""
    shells = {int(r["id"]) for r in table_rows(scene, "patches") if r["kind"].strip() in ("plate", "gmsh")}
    rows = table_rows(scene, "joints")
    sides = [(int(r["patch_a"]) in shells) + (int(r["patch_b"]) in shells) for r in rows]
    return len(rows), sum(sides), sum(1 for n in sides if n)


def main():
    if len(sys.argv) < 6 or sys.argv[4] != "--":
        sys.exit(__doc__)
    scene, ranks, info, cmd = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[5:]
    status, printed, out = info_files.run(cmd, info)
    if status != 0:
        print(printed[-3000:])
        sys.exit(f"the run exited {status}")
    pat = re.compile(r"^\[(\d+)\] (?:<\w+> )?\S+: Read and laid out (\d+) of (\d+) shell parts \((\d+) of (\d+) mesh nodes\)")
    kept_pat = re.compile(r"^\[(\d+)\] (?:<\w+> )?\S+: Kept the components of (\d+) of (\d+) joints on this rank past the set-up")
    mesh_pat = re.compile(r"^\[(\d+)\] (?:<\w+> )?\S+: Kept the meshes of (\d+) of (\d+) shell patches \((\d+) nodes\) on this rank past the set-up")
    table_pat = re.compile(r"^\[(\d+)\] (?:<\w+> )?\S+: Read the fastener table's (\d+) rows on this rank")
    sent_pat = re.compile(r"^\[(\d+)\] (?:<\w+> )?\S+: Attaching (\d+) of (\d+) joints \((\d+) joint sides\) on this rank's shell parts")
    seen, kept, table, sent, meshes = {}, {}, {}, {}, {}
    for line in out.splitlines():
        g = pat.match(line)
        if g:
            seen[int(g.group(1))] = tuple(int(x) for x in g.groups()[1:])
        g = kept_pat.match(line)
        if g:
            kept[int(g.group(1))] = (int(g.group(2)), int(g.group(3)))
        g = mesh_pat.match(line)
        if g:
            meshes[int(g.group(1))] = (int(g.group(2)), int(g.group(3)))
        g = table_pat.match(line)
        if g:
            table[int(g.group(1))] = int(g.group(2))
        g = sent_pat.match(line)
        if g:
            sent[int(g.group(1))] = tuple(int(x) for x in g.groups()[1:])
    P, N = scene_parts(scene)
    J, S, JS = scene_joints(scene)
    bad = []
    if sorted(seen) != list(range(ranks)):
        bad.append(f"lines from ranks {sorted(seen)}, expected 0..{ranks - 1}")
    for r, (k, p, n, tot) in sorted(seen.items()):
        print(f"rank {r}: {k} of {p} shell parts, {n} of {tot} mesh nodes")
        if p != P or tot != N:
            bad.append(f"rank {r} counts {p} parts of {tot} nodes; the scene has {P} parts of {N} nodes")
        if ranks > 1 and P > 1 and k == P:
            bad.append(f"rank {r} read every part")
    if sum(v[0] for v in seen.values()) != P:
        bad.append(f"the ranks read {sum(v[0] for v in seen.values())} parts in all, the scene has {P}")
    if sum(v[2] for v in seen.values()) != N:
        bad.append(f"the ranks read {sum(v[2] for v in seen.values())} nodes in all, the scene has {N}")
    if sorted(kept) != list(range(ranks)):
        bad.append(f"joint lines from ranks {sorted(kept)}, expected 0..{ranks - 1}")
    for r, (j, tot) in sorted(kept.items()):
        print(f"rank {r}: kept {j} of {tot} joints")
        if tot != J:
            bad.append(f"rank {r} counts {tot} joints; the scene has {J}")
        if ranks > 1 and J > 1 and j == J:
            bad.append(f"rank {r} kept every joint")
    if sum(v[0] for v in kept.values()) != J:
        bad.append(f"the ranks kept {sum(v[0] for v in kept.values())} joints in all, the scene has {J}")
    if sorted(meshes) != list(range(ranks)):
        bad.append(f"patch mesh lines from ranks {sorted(meshes)}, expected 0..{ranks - 1}")
    totals = {tot for m, tot in meshes.values()}
    for r, (m, tot) in sorted(meshes.items()):
        print(f"rank {r}: kept the meshes of {m} of {tot} shell patches")
    if len(totals) != 1:
        bad.append(f"the ranks count {sorted(totals)} shell patches, not one number")
    elif sum(m for m, tot in meshes.values()) != next(iter(totals)):
        bad.append(f"the ranks kept {sum(m for m, tot in meshes.values())} patch meshes in all, of {next(iter(totals))} patches: each must be kept by its owner alone")
    if table != {0: J}:
        bad.append(f"the fastener table was read as {table} (rank: rows), expected {{0: {J}}}: by rank 0 alone")
    if sorted(sent) != list(range(ranks)):
        bad.append(f"joint sharing lines from ranks {sorted(sent)}, expected 0..{ranks - 1}")
    for r, (a, tot, s) in sorted(sent.items()):
        print(f"rank {r}: sent {a} of {tot} joints, {s} joint sides on its parts")
        if tot != J:
            bad.append(f"rank {r} was told of {tot} joints; the scene has {J}")
    if sum(v[2] for v in sent.values()) != S:
        bad.append(f"the ranks attached {sum(v[2] for v in sent.values())} joint sides in all, the scene has {S} on shell parts")
    total_sent = sum(v[0] for v in sent.values())
    if not JS <= total_sent <= S:
        bad.append(f"the ranks were sent {total_sent} joints in all; each of the {JS} joints with a side on a shell part goes to its parts' holders, one or two ranks, at most {S}")
    if bad:
        sys.exit("FAIL: " + "; ".join(bad))
    print(f"every one of the {P} shell parts ({N} nodes) read by one rank of {ranks}, each of its {J} joints kept by one")


if __name__ == "__main__":
    main()
