#!/usr/bin/env python3
"""LinuxCNC's interpreter as the oracle of the G-code reader.

Runs every program of a corpus through `rs274` (LinuxCNC 2.9's stand-alone
interpreter, Debian's linuxcnc-uspace) and through `contour gcode --format
moves`, and compares every move: kind, end point, arc centre, plane, sense,
feed, and every dwell, tool change, spindle start, coolant start, pause and
program end, in order, to 1e-4 in the program's units (rs274 prints 4
decimals). A program that one refuses must be refused by the other.

This file shares no code with the reader (model/gcode): it reads rs274's
canonical calls (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, DWELL,
SET_FEED_RATE, USE_LENGTH_UNITS, SET_G5X_OFFSET, SET_G92_OFFSET,
USE_TOOL_LENGTH_OFFSET, SELECT_PLANE, ...) and turns them into machine
millimetres itself: machine = (printed + G5x offset + G92 offset) + tool
length offset on Z, each converted to mm in the units in effect when printed.

  rs274_oracle.py RS274 CONTOUR CORPUS_DIR [PROGRAM.ngc ...]

CORPUS_DIR/tools.tbl (if present) is the tool table, Z in mm; rs274 reads
its table in inches here, so it is given a copy with Z / 25.4. Programs in
CORPUS_DIR/refused/ must be refused by both. Exit status 0 when all agree.
"""
import os
import re
import subprocess
import sys
import tempfile

TOL = 1e-4  # program units

CALL = re.compile(r"^\s*\d+\s+N\S*\s+([A-Z_0-9]+)\((.*)\)\s*$")


def numbers(args):
    return [float(x) for x in re.findall(r"[-+]?\d+\.\d+|[-+]?\d+", args)]


class Canon:
    """rs274's canonical calls as moves in machine mm."""

    def __init__(self):
        self.unit = 1.0  # mm per program unit, as the calls are printed
        self.g5x = [0.0, 0.0, 0.0]
        self.g92 = [0.0, 0.0, 0.0]
        self.tlo = 0.0
        self.feed = 0.0  # mm/min
        self.plane = "G17"
        self.pos = [0.0, 0.0, 0.0]  # the machine starts at its origin (as the reader)
        self.moves = []  # (kind, fields...)

    def machine(self, xyz):
        m = [(v * self.unit) + self.g5x[i] + self.g92[i] for i, v in enumerate(xyz)]
        m[2] += self.tlo
        return m

    def call(self, name, args):
        n = numbers(args)
        if name == "USE_LENGTH_UNITS":
            self.unit = 25.4 if "INCHES" in args else 1.0
        elif name == "SET_G5X_OFFSET":
            self.g5x = [v * self.unit for v in n[1:4]]
        elif name == "SET_G92_OFFSET":
            self.g92 = [v * self.unit for v in n[0:3]]
        elif name == "USE_TOOL_LENGTH_OFFSET":
            self.tlo = n[2] * self.unit
        elif name == "SET_FEED_RATE":
            self.feed = n[0] * self.unit
        elif name == "SELECT_PLANE":
            self.plane = {"CANON_PLANE_XY": "G17", "CANON_PLANE_XZ": "G18", "CANON_PLANE_YZ": "G19"}[args.strip()]
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            self.straight(name, n)
        elif name == "ARC_FEED":
            self.arc(n)
        elif name == "DWELL":
            self.moves.append(("DWELL", n[0]))
        else:
            self.event(name, n)

    def straight(self, name, n):
        end = self.machine(n[0:3])
        if all(abs(a - b) < 1e-9 for a, b in zip(end, self.pos)):
            return  # a move of length zero moves nothing (the reader drops it too)
        self.pos = end
        if name == "STRAIGHT_TRAVERSE":
            self.moves.append(("RAPID", end, self.unit))
        else:
            self.moves.append(("LINE", self.feed, end, self.unit))

    def arc(self, n):
        first_end, second_end, first_c, second_c, rotation, axis_end = n[0:6]
        # The canon's (first, second, axis) order per plane.
        order = {"G17": (0, 1, 2), "G18": (2, 0, 1), "G19": (1, 2, 0)}[self.plane]
        end_prog, centre_prog = [0.0] * 3, [0.0] * 3
        end_prog[order[0]], end_prog[order[1]], end_prog[order[2]] = first_end, second_end, axis_end
        centre_prog[order[0]], centre_prog[order[1]] = first_c, second_c
        end = self.machine(end_prog)
        centre = self.machine(centre_prog)
        # The centre's normal coordinate is not printed: the arc's start.
        start = self.pos
        centre[order[2]] = start[order[2]]
        if abs(rotation) != 1:
            raise ValueError("multi-turn arc (rotation %g)" % rotation)
        self.pos = end
        self.moves.append(("ARC", self.feed, self.plane, "CCW" if rotation > 0 else "CW", end, centre, self.unit))

    def event(self, name, n):
        simple = {"START_SPINDLE_CLOCKWISE": "M3", "START_SPINDLE_COUNTERCLOCKWISE": "M4", "MIST_ON": "M7",
                  "FLOOD_ON": "M8", "PROGRAM_STOP": "M0", "OPTIONAL_PROGRAM_STOP": "M1", "PROGRAM_END": "END"}
        if name in simple:
            self.moves.append(("EVENT", simple[name]))
        elif name == "CHANGE_TOOL":
            self.moves.append(("EVENT", "M6 T%d" % int(n[0])))


def run_rs274(rs274, program, tools_in):
    cmd = [rs274, "-b", "-g"]
    if tools_in:
        cmd[1:1] = ["-t", tools_in]
    r = subprocess.run(cmd + [program], stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    canon = Canon()
    problem = None
    for line in r.stdout.splitlines():
        m = CALL.match(line)
        if m:
            canon.call(m.group(1), m.group(2))
    if r.returncode != 0:
        problem = " ".join((r.stdout + r.stderr).split("\n")[-4:]).strip() or "exit %d" % r.returncode
        for line in (r.stdout + r.stderr).splitlines():
            if line and not CALL.match(line) and line.strip() != "executing":
                problem = line.strip()
                break
    return canon.moves, problem


def run_contour(contour, program, tools_mm):
    cmd = [contour, "gcode", program, "--format", "moves"]
    if tools_mm:
        cmd += ["--tool-table", tools_mm]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    if r.returncode != 0:
        return None, r.stderr.strip() or "exit %d" % r.returncode
    moves = []
    for line in r.stdout.splitlines():
        f = line.split()
        if f[0] == "RAPID":
            moves.append(("RAPID", [float(v) for v in f[2:5]]))
        elif f[0] == "LINE":
            moves.append(("LINE", float(f[1]), [float(v) for v in f[2:5]]))
        elif f[0] == "ARC":
            moves.append(("ARC", float(f[1]), f[2], f[3], [float(v) for v in f[4:7]], [float(v) for v in f[7:10]]))
        elif f[0] == "DWELL":
            moves.append(("DWELL", float(f[1])))
        elif f[0] == "EVENT" and (f[1] in ("M3", "M4", "M7", "M8", "M0", "M1") or f[1] == "M6"):
            moves.append(("EVENT", " ".join(f[1:])))
        elif f[0] == "END":
            moves.append(("EVENT", "END"))
    return moves, None


def close(a, b, unit):
    return all(abs(x - y) / unit <= TOL for x, y in zip(a, b))


def compare(expected, got):
    """The first difference, or None. expected: rs274's; got: contour's."""
    for k, (e, g) in enumerate(zip(expected, got)):
        where = "move %d" % (k + 1)
        if e[0] != g[0]:
            return "%s: rs274 %s, contour %s" % (where, e, g)
        kind = e[0]
        if kind == "RAPID" and not close(e[1], g[1], e[2]):
            return "%s: rapid end rs274 %s, contour %s" % (where, e[1], g[1])
        if kind == "LINE" and not (close(e[2], g[2], e[3]) and close([e[1]], [g[1]], e[3])):
            return "%s: line rs274 F%g %s, contour F%g %s" % (where, e[1], e[2], g[1], g[2])
        if kind == "ARC":
            unit = e[6]
            if e[2] != g[2] or e[3] != g[3]:
                return "%s: arc plane/sense rs274 %s %s, contour %s %s" % (where, e[2], e[3], g[2], g[3])
            if not (close(e[4], g[4], unit) and close(e[5], g[5], unit) and close([e[1]], [g[1]], unit)):
                return "%s: arc rs274 F%g end %s centre %s, contour F%g end %s centre %s" % (
                    where, e[1], e[4], e[5], g[1], g[4], g[5])
        if kind == "DWELL" and abs(e[1] - g[1]) > TOL:
            return "%s: dwell rs274 %g, contour %g" % (where, e[1], g[1])
        if kind == "EVENT" and e[1] != g[1]:
            return "%s: rs274 %s, contour %s" % (where, e[1], g[1])
    if len(expected) != len(got):
        return "rs274 has %d moves and events, contour %d" % (len(expected), len(got))
    return None


def inch_tool_table(tools_mm, directory):
    out = os.path.join(directory, "tools_in.tbl")
    with open(tools_mm) as src, open(out, "w") as dst:
        for line in src:
            body = line.split(";")[0]
            body = re.sub(r"([Zz])\s*([-+]?[\d.]+)", lambda m: "Z%.10f" % (float(m.group(2)) / 25.4), body)
            dst.write(body.strip() + "\n")
    return out


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    rs274, contour, corpus = argv[1], argv[2], argv[3]
    tools_mm = os.path.join(corpus, "tools.tbl")
    tools_mm = tools_mm if os.path.exists(tools_mm) else None
    programs = argv[4:] or sorted(
        [os.path.join(corpus, f) for f in os.listdir(corpus) if f.endswith(".ngc")] +
        [os.path.join(corpus, "refused", f) for f in os.listdir(os.path.join(corpus, "refused"))
         if f.endswith(".ngc")])
    fails = moves_compared = refused = 0
    with tempfile.TemporaryDirectory() as tmp:
        tools_in = inch_tool_table(tools_mm, tmp) if tools_mm else None
        for prog in programs:
            name = os.path.relpath(prog, corpus)
            expected, e_problem = run_rs274(rs274, prog, tools_in)
            got, g_problem = run_contour(contour, prog, tools_mm)
            want_refused = os.path.basename(os.path.dirname(prog)) == "refused"
            if e_problem or g_problem:
                if e_problem and g_problem and want_refused:
                    refused += 1
                    continue
                print("FAIL %s: rs274: %s; contour: %s" % (name, e_problem or "accepted", g_problem or "accepted"))
                fails += 1
                continue
            if want_refused:
                print("FAIL %s: in refused/ but both accept it" % name)
                fails += 1
                continue
            why = compare(expected, got)
            if why:
                print("FAIL %s: %s" % (name, why))
                fails += 1
            else:
                moves_compared += len(expected)
    print("rs274 oracle: %d programs, %d moves and events equal, %d refused by both, %d failed" % (
        len(programs), moves_compared, refused, fails))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
