#!/usr/bin/python3
"""Checks that a Nastran deck is read by rank 0 alone and that each shell part's mesh goes from
rank 0 to the one rank that lays it out (lib/nastran/petsc.cpp, io/nastran.cpp, patch/share.cpp).

  check_deck_per_rank.py DECK RANKS INFO -- COMMAND...

Runs COMMAND (an mpirun of the driver on DECK with -info INFO, which writes each rank's lines to
its own file INFO.r: info_files.py) and reads each rank's lines (PETSc 3.18 writes them as
'[r] <sys> Function(): ...')

  [r] ReadDeckOn(): Read the Nastran deck 'DECK' on this rank alone
  [r] SendRank0Meshes(): Sent s shell part meshes (b bytes) to the ranks that lay them out
  [r] SendRank0Meshes(): Received k shell part meshes (b bytes) from rank 0
  [r] LayoutCreate(): Read and laid out K of P shell parts (n of N mesh nodes) on this rank

the last three once per set-up (a deck's subcases with different SPC sets are separate set-ups).

The reference is the deck itself, read here (small, large or free field, INCLUDE followed): P must be the number
of properties of its CQUAD4/CTRIA3 elements and N the sum over them of the grids of each
property's elements (a grid on the elements of two properties is a node of each part). The deck
must be read once, on rank 0. In each set-up the K must add up to P and the n to N (every part laid
out once), with several ranks no rank may lay out every part, every rank but 0 must have received
exactly the meshes it lays out, and rank 0 must have sent P - K_0 meshes, as many bytes as the
others received.
"""
import os
import re
import sys

import info_files


def shell_cards(path):
    """(card, fields after the name) of each CQUAD4 and CTRIA3 of one file, in any of the three
    field formats: small (8-character fields), large (a name ending in '*', 16-character fields,
    continued on lines that start with '*') and free (fields between commas). INCLUDE lines are
    returned as ('INCLUDE', [file name]), a quoted name joined over its lines."""
    lines = [l.rstrip("\n") for l in open(path)]
    i = 0
    while i < len(lines):
        line = lines[i]
        i += 1
        if line.startswith("INCLUDE"):
            name = line.split(None, 1)[1].strip()
            if name[0] in "'\"":
                # a quoted name may go on over several lines, each piece trimmed (docs/nastran.md);
                # what follows its closing quote (a $ comment) is not part of it
                while name.find(name[0], 1) < 0 and i < len(lines):
                    name += lines[i].strip()
                    i += 1
                name = name[1:name.find(name[0], 1)]
            else:
                name = name.split("$", 1)[0].strip()
            yield "INCLUDE", [name]
            continue
        if "," in line[:16]:
            fields = [f.strip() for f in line.split(",")]
            if fields[0] in ("CQUAD4", "CTRIA3"):
                yield fields[0], fields[1:]
            continue
        name = line[:8].strip()
        if name.rstrip("*") not in ("CQUAD4", "CTRIA3"):
            continue
        if name.endswith("*"):
            fields = [line[8 + 16 * k:24 + 16 * k].strip() for k in range(4)]
            while i < len(lines) and lines[i].startswith("*"):
                fields += [lines[i][8 + 16 * k:24 + 16 * k].strip() for k in range(4)]
                i += 1
            yield name[:-1], fields
        else:
            yield name, [line[8 * k:8 * k + 8].strip() for k in range(1, 9)]


def deck_parts(path):
    """{pid: set of grids} of the deck's CQUAD4 and CTRIA3, INCLUDEs followed."""
    parts = {}
    here = os.path.dirname(path)
    for card, fields in shell_cards(path):
        if card == "INCLUDE":
            for pid, grids in deck_parts(os.path.join(here, fields[0])).items():
                parts.setdefault(pid, set()).update(grids)
            continue
        nodes = 4 if card == "CQUAD4" else 3
        parts.setdefault(int(fields[1]), set()).update(int(g) for g in fields[2:2 + nodes])
    return parts


def main():
    if len(sys.argv) < 6 or sys.argv[4] != "--":
        sys.exit(__doc__)
    deck, ranks, info, command = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[5:]
    parts = deck_parts(deck)
    P, N = len(parts), sum(len(g) for g in parts.values())
    status, printed, out = info_files.run(command, info)
    if status != 0:
        sys.exit(printed[-20000:] + "\nthe run failed (exit code %d)" % status)
    readers = [int(r) for r in re.findall(r"^\[(\d+)\] (?:<\w+> )?ReadDeckOn\(\): Read the Nastran deck '.*' on this rank alone$", out, re.M)]
    laid = {}  # rank -> [(K, P, n, N)] in order of set-up
    for r, k, p, n, nn in re.findall(r"^\[(\d+)\] (?:<\w+> )?LayoutCreate\(\): Read and laid out (\d+) of (\d+) shell parts \((\d+) of (\d+) mesh nodes\) on this rank$", out, re.M):
        laid.setdefault(int(r), []).append(tuple(map(int, (k, p, n, nn))))
    sent, got = {}, {}  # rank -> [(count, bytes)] in order of set-up
    for r, verb, k, b in re.findall(r"^\[(\d+)\] (?:<\w+> )?SendRank0Meshes\(\): (Sent|Received) (\d+) shell part meshes \((\d+) bytes\)", out, re.M):
        (sent if verb == "Sent" else got).setdefault(int(r), []).append((int(k), int(b)))
    errors = []
    if readers != [0]:
        errors.append("the deck must be read once, by rank 0; read by rank(s) %s" % readers)
    if sorted(laid) != list(range(ranks)):
        errors.append("ranks that laid out parts: %s, expected 0..%d" % (sorted(laid), ranks - 1))
    setups = len(laid.get(0, []))
    if setups == 0 or any(len(v) != setups for v in laid.values()):
        errors.append("each rank must lay out the parts once per set-up: %s" % {r: len(v) for r, v in laid.items()})
    for s in range(setups if not errors else 0):
        rows = {r: laid[r][s] for r in laid}
        for r, (k, p, n, nn) in rows.items():
            if p != P or nn != N:
                errors.append("set-up %d, rank %d: %d parts of %d nodes, the deck has %d of %d" % (s, r, p, nn, P, N))
        if sum(v[0] for v in rows.values()) != P or sum(v[2] for v in rows.values()) != N:
            errors.append("set-up %d: the ranks laid out %d parts and %d nodes, the deck has %d and %d"
                          % (s, sum(v[0] for v in rows.values()), sum(v[2] for v in rows.values()), P, N))
        if ranks > 1 and P >= ranks and any(v[0] == P for v in rows.values()):
            errors.append("set-up %d: one rank laid out every part: %s" % (s, rows))
        # A rank logs its meshes only when it sent or received some: count the set-ups in order.
        received = 0
        for r in range(1, ranks):
            k = rows[r][0]
            if k == 0:
                continue
            mine = got.get(r, [])
            index = sum(1 for t in range(s) if laid[r][t][0] > 0)
            if index >= len(mine) or mine[index][0] != k:
                errors.append("set-up %d: rank %d lays out %d parts but received %s meshes from rank 0" % (s, r, k, mine[index][0] if index < len(mine) else 0))
            else:
                received += mine[index][1]
        expect = P - rows[0][0]
        index = sum(1 for t in range(s) if P - laid[0][t][0] > 0)
        mine = sent.get(0, [])
        count, nbytes = mine[index] if expect > 0 and index < len(mine) else (0, 0)
        if count != expect:
            errors.append("set-up %d: rank 0 sent %d meshes, the other ranks lay out %d" % (s, count, expect))
        if nbytes != received:
            errors.append("set-up %d: rank 0 sent %d bytes, the others received %d" % (s, nbytes, received))
    if [r for r in sent if r != 0]:
        errors.append("only rank 0 may send meshes: %s" % sorted(sent))
    if errors:
        lines = [l for l in out.split("\n") if re.search(r"ReadDeckOn|SendRank0Meshes|LayoutCreate|error", l)]
        sys.exit("\n".join(lines) + "\n" + "\n".join(errors))
    print("deck read on rank 0 alone; %d set-up(s): %d parts, %d nodes laid out once over %d rank(s), "
          "every mesh sent by rank 0 to its holder" % (setups, P, N, ranks))


if __name__ == "__main__":
    main()
