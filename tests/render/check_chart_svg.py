#!/usr/bin/env python3
"""Reads a chart SVG written by `robotsim plot` with python3's XML parser and
checks it against the CSV of the same run (docs/render.md, "Charts of a run").

    check_chart_svg.py CHART.svg CHART.csv [--collision SECONDS] [--lines T,T,...]

It finds the lanes by their background colour, works out from the CSV which
lane shows which columns (the arm's motors, the TCP, the gripper when there
is a `held` column, inputs, outputs, then the source lines), and checks:
every vertex of each series is at a sample, and every sample lies on the
line where its value puts it on the lane's own scale (the column's lowest
to highest value, 4 px inside the lane; the tool centre point's x, y and z
each in a lane of its own, on its own scale); each input and output row is
bright (its lane's colour) exactly where the CSV says ON, high in the row,
and dim (dark gray) exactly where it says OFF, low in the row, so that a
line that never turns on has nothing bright; a
red mark stands at the collision's moment (given to the millisecond); the
source-line ticks stand at the given moments. Prints "ok: ..." and exits 0,
or prints what differs and exits 1. Used by tests/render/test_chart.cpp.
"""
import argparse
import csv
import re
import sys
import xml.etree.ElementTree as ET

# runtime/render/chart_draw.h's colours (EGA) and layout rules.
LANE = (0x18, 0x1B, 0x27)
MOTOR, GRIPPER = (0x55, 0xFF, 0xFF), (0xFF, 0xFF, 0xFF)
TCP = [(0xFF, 0x55, 0x55), (0x55, 0xFF, 0x55), (0x55, 0x55, 0xFF)]
INPUT, OUTPUT = (0x55, 0xFF, 0x55), (0xFF, 0x55, 0x55)
OFF = (0x55, 0x55, 0x55)
LINE_TICK, COLLISION = (0xAA, 0xAA, 0xAA), (0xAA, 0x00, 0x00)
PAD, ROW = 4.0, 8.0
# cairo writes coordinates in 1/256 px: what two positions may differ by.
EPS = 0.01

problems = []


def fail(message):
    problems.append(message)


def colour(text):
    """'rgb(33.333333%,100%,100%)' or 'rgb(85,255,255)' -> (85, 255, 255)."""
    m = re.fullmatch(r'\s*rgb\(([^)]*)\)\s*', text or '')
    if not m:
        return None
    out = []
    for part in m.group(1).split(','):
        part = part.strip()
        out.append(round(float(part[:-1]) * 255 / 100) if part.endswith('%') else int(part))
    return tuple(out)


def style(element):
    result = {}
    for item in (element.get('style') or '').split(';'):
        if ':' in item:
            key, value = item.split(':', 1)
            result[key.strip()] = value.strip()
    return result


def subpaths(d):
    """A path's d as lists of (x, y) points, one list per M."""
    out = []
    tokens = re.findall(r'[MLCZ]|-?\d+(?:\.\d+)?(?:e-?\d+)?', d)
    i = 0
    while i < len(tokens):
        t = tokens[i]
        if t == 'M':
            out.append([(float(tokens[i + 1]), float(tokens[i + 2]))])
            i += 3
        elif t == 'L':
            out[-1].append((float(tokens[i + 1]), float(tokens[i + 2])))
            i += 3
        elif t == 'C':
            out[-1].append((float(tokens[i + 5]), float(tokens[i + 6])))
            i += 7
        else:
            i += 1
    return [p for p in out if len(p) > 1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('svg')
    ap.add_argument('csv')
    ap.add_argument('--collision', type=float)
    ap.add_argument('--lines')
    args = ap.parse_args()

    with open(args.csv, newline='') as f:
        rows = list(csv.reader(f))
    header, data = rows[0], rows[1:]
    col = {name: i for i, name in enumerate(header)}
    times = [float(r[0]) for r in data]
    end = times[-1]
    values = {name: [float(r[i]) for r in data] for name, i in col.items()}
    motors = header[1:header.index('tcp_x')]
    has_gripper = 'held' in col
    arm = motors[:-1] if has_gripper else motors

    paths = []  # (fill, stroke, points lists)
    for el in ET.parse(args.svg).getroot().iter('{http://www.w3.org/2000/svg}path'):
        s = style(el)
        paths.append((colour(s.get('fill')), colour(s.get('stroke')), float(s.get('stroke-width', '1')),
                      subpaths(el.get('d', ''))))

    boxes = []
    for fill, stroke, _, subs in paths:
        if fill == LANE:
            for pts in subs:
                xs, ys = [p[0] for p in pts], [p[1] for p in pts]
                boxes.append((min(xs), min(ys), max(xs), max(ys)))
    boxes.sort(key=lambda b: b[1])
    expected_lanes = len(arm) + 3 + (1 if has_gripper else 0) + 2 + 1
    if len(boxes) != expected_lanes:
        print(f'found {len(boxes)} lanes, expected {expected_lanes} for columns {header}')
        return 1
    left, right = boxes[0][0], boxes[0][2]

    def x_of(t):
        return left + (right - left) * t / end if end > 0 else left

    def inside(pts, box):
        return all(box[0] - EPS <= x <= box[2] + EPS and box[1] - EPS <= y <= box[3] + EPS for x, y in pts)

    def same_positions(a, b):
        return len(a) == len(b) and all(abs(p - q) <= EPS for p, q in zip(a, b))

    def strokes(colour_, box):
        return [pts for _, stroke, _, subs in paths if stroke == colour_ for pts in subs if inside(pts, box)]

    def sample_at(x):
        """The sample drawn at x (every vertex of a series is one)."""
        best = min(range(len(times)), key=lambda i: abs(x_of(times[i]) - x))
        if abs(x_of(times[best]) - x) > EPS:
            fail(f'a vertex at x {x} is at no sample')
        return best

    def check_analog(columns, colours, box, lane):
        lo = min(min(values[c]) for c in columns)
        hi = max(max(values[c]) for c in columns)
        if hi - lo < 1e-9:
            lo, hi = lo - 1, hi + 1
        for c, colour_ in zip(columns, colours):
            found = strokes(colour_, box)
            if len(found) != 1:
                fail(f'lane {lane}: {len(found)} paths of column {c}, expected 1')
                continue
            pts = found[0]
            if abs(pts[0][0] - left) > EPS or abs(pts[-1][0] - right) > EPS:
                fail(f'lane {lane}: column {c} does not span the time axis')
            for x, y in pts:
                v = values[c][sample_at(x)]
                want = box[3] - PAD - (v - lo) / (hi - lo) * (box[3] - box[1] - 2 * PAD)
                if abs(y - want) > EPS:
                    fail(f'lane {lane}: column {c} at x {x}: y {y}, its value {v} puts it at {want}')
            # Every sample lies on the line drawn (cairo merges the vertices
            # of collinear samples into one segment).
            k = 0
            for i, t in enumerate(times):
                x = x_of(t)
                while k + 2 < len(pts) and pts[k + 1][0] < x - EPS:
                    k += 1
                (x0, y0), (x1, y1) = pts[k], pts[k + 1]
                drawn = y0 if abs(x1 - x0) < 1e-9 else y0 + (y1 - y0) * (x - x0) / (x1 - x0)
                v = values[c][i]
                want = box[3] - PAD - (v - lo) / (hi - lo) * (box[3] - box[1] - 2 * PAD)
                if abs(drawn - want) > 2 * EPS:
                    fail(f'lane {lane}: column {c} at {t} s: the line passes y {drawn:.3f}, its value {v} is at {want:.3f}')

    def stretches(column, on):
        """The x ranges where the CSV has the column ON (or OFF): each from
        the sample where it starts to the sample where it ends (or the end)."""
        v = values[column]
        out, i = [], 0
        while i < len(v):
            j = i + 1
            while j < len(v) and (v[j] > 0.5) == (v[i] > 0.5):
                j += 1
            if (v[i] > 0.5) == on:
                out.append((x_of(times[i]), x_of(times[min(j, len(v) - 1)])))
            i = j
        return out

    def check_digital(prefix, colour_, box, lane):
        for r in range(8):
            c = f'{prefix}{r + 1}'
            top = box[1] + r * ROW
            row_box = (box[0], top, box[2], top + ROW)
            high, low = top + 1.5, top + ROW - 1.5
            for on, want_colour, level in ((True, colour_, high), (False, OFF, low)):
                found = strokes(want_colour, row_box)
                # Horizontal runs at the level, merged where cairo split them.
                runs = sorted((min(a[0], b[0]), max(a[0], b[0])) for pts in found for a, b in zip(pts, pts[1:])
                              if abs(a[1] - level) < EPS and abs(b[1] - level) < EPS)
                merged = []
                for x0, x1 in runs:
                    if merged and x0 <= merged[-1][1] + EPS:
                        merged[-1] = (merged[-1][0], max(merged[-1][1], x1))
                    else:
                        merged.append((x0, x1))
                want = [w for w in stretches(c, on) if w[1] - w[0] > EPS]
                if len(merged) != len(want) or any(abs(a[0] - b[0]) > EPS or abs(a[1] - b[1]) > EPS
                                                   for a, b in zip(merged, want)):
                    fail(f'{c}: {"ON" if on else "OFF"} drawn at x {merged}, the CSV has it {"ON" if on else "OFF"} '
                         f'at x {want}')
                # Nothing of the colour anywhere else in the row: bright only while ON.
                for pts in found:
                    for x, y in pts:
                        if abs(y - level) > EPS and not (on and abs(y - low) < EPS):
                            fail(f'{c}: a {"bright" if on else "dim"} vertex at y {y}, neither its level nor an edge')
            if not any(values[c]) and strokes(colour_, row_box):
                fail(f'{c}: never ON, yet drawn in its bright colour')

    lane = 0
    for m in arm:
        check_analog([m], [MOTOR], boxes[lane], f'{lane} ({m})')
        lane += 1
    for axis, column in enumerate(['tcp_x', 'tcp_y', 'tcp_z']):
        check_analog([column], [TCP[axis]], boxes[lane], f'{lane} ({column})')
        lane += 1
    if has_gripper:
        check_analog([motors[-1]], [GRIPPER], boxes[lane], f'{lane} (gripper)')
        lane += 1
    check_digital('in', INPUT, boxes[lane], f'{lane} (inputs)')
    check_digital('out', OUTPUT, boxes[lane + 1], f'{lane + 1} (outputs)')
    lines_box = boxes[lane + 2]

    marks = [pts for _, stroke, width, subs in paths if stroke == COLLISION for pts in subs]
    if args.collision is not None:
        # The moment is given to the millisecond: half of one is the tolerance.
        tolerance = (right - left) * 0.0005 / end + EPS
        want = x_of(args.collision)
        hits = [pts for pts in marks if abs(pts[0][0] - want) <= tolerance and abs(pts[1][0] - pts[0][0]) < 1e-6
                and pts[0][1] <= boxes[0][1] + EPS and pts[1][1] >= lines_box[3] - EPS]
        if len(hits) != 1:
            fail(f'no red mark across the lanes at x {want} ({args.collision} s); red marks at '
                 f'{[pts[0][0] for pts in marks]}')
    elif marks:
        fail(f'red marks at {[pts[0][0] for pts in marks]}, no collision expected')

    if args.lines:
        ticks = sorted(pts[0][0] for pts in strokes(LINE_TICK, lines_box))
        want = sorted(x_of(float(t)) for t in args.lines.split(','))
        if not same_positions(ticks, want):
            fail(f'source line ticks at x {ticks}, expected {want}')

    if problems:
        print('\n'.join(problems[:40]))
        return 1
    print(f'ok: {len(boxes)} lanes, {len(times)} samples, {len(marks)} collision marks')
    return 0


if __name__ == '__main__':
    sys.exit(main())
