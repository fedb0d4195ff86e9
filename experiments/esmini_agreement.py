#!/usr/bin/env python3
"""How truly esmini plays sitcov's exports (src/main/java/sitcov/export/README.md, "Playing an export").

Plays every .xosc under the folders given in esmini, headless, and compares what esmini did with what the
file says sitcov did:

- headings: a recorded run's vehicles, at every tick a trajectory or a teleport places them on the map,
  |esmini's heading - sitcov's| (sitcov's from the file: its vertices, linear between them as the export
  keeps them within 0.05 degrees), with the positions' largest difference beside it;
- collisions: esmini's `Collision between A and B` against the contacts the file declares, matched by
  the pair and a start within a tick of the declared one; of those esmini alone reports, how many involve
  the ego and how many were not over between two samples (sitcov sees contacts at its ticks only); and how
  many of the file's contact events esmini started;
- routes: a situation's ego route, kept unless esmini says it is not valid and ignores it.

Needs an esmini you build yourself (https://github.com/esmini/esmini); the build and tests never do.
Usage: python3 experiments/esmini_agreement.py PATH/TO/esmini EXPORT_DIR... [--each]
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

STEP = 0.05        # esmini's fixed time step, a quarter of sitcov's tick
TICK = 0.2
WORLD = (0.0, 0.0, 200.0, 100.0)
COLLISION = re.compile(r"^\[([0-9.]+)\] \[\w+\] Collision between (\S+) and (\S+?)( dissolved)?$")
ROUTE_DROPPED = re.compile(r"Route .* is not valid")
EVENT_STARTED = re.compile(r"^\[[0-9.]+\] \[info\] (.*) standbyState -> startTransition -> runningState$")


def play(esmini, xosc, workdir, step):
    """Runs esmini on one file; returns its log's lines and the CSV log's path."""
    csv_path = os.path.join(workdir, "run.csv")
    log_path = os.path.join(workdir, "log.txt")
    subprocess.run([esmini, "--headless", "--osc", os.path.abspath(xosc), "--fixed_timestep", str(step),
                    "--traj_filter", "0", "--csv_logger", csv_path, "--collision", "--disable_stdout",
                    "--logfile_path", log_path], cwd=workdir, check=True, stdout=subprocess.DEVNULL)
    with open(log_path, encoding="utf-8", errors="replace") as f:
        return f.read().splitlines(), csv_path


def esmini_poses(csv_path):
    """{(entity, step index): (x, y, h)} from esmini's CSV log, h in radians."""
    poses = {}
    with open(csv_path, newline="") as f:
        rows = csv.reader(f)
        header = None
        for row in rows:
            if row and row[0].startswith("Index"):
                header = [c.strip() for c in row]
                break
        per = 31  # columns per object, after Index and TimeStamp
        for row in rows:
            cells = [c.strip() for c in row]
            k = round(float(cells[1]) / STEP)
            for o in range(2, len(cells) - per + 1, per):
                name = cells[o]
                if not name:
                    continue
                poses[(name, k)] = (float(cells[o + 11]), float(cells[o + 12]), float(cells[o + 24]))
    return poses


def world_pose(position):
    w = position.find("WorldPosition")
    return float(w.get("x")), float(w.get("y")), float(w.get("h", "0"))


def actor_of(root):
    """{id(Event element): entity} through each ManeuverGroup's actor."""
    out = {}
    for group in root.iter("ManeuverGroup"):
        refs = group.find("Actors").findall("EntityRef")
        for event in group.iter("Event"):
            out[id(event)] = refs[0].get("entityRef") if refs else None
    return out


def start_time(event):
    t = event.find("StartTrigger").find(".//SimulationTimeCondition")
    return float(t.get("value")) if t is not None else None


def sitcov_poses(root):
    """{(entity, tick): (x, y, h)}: where the file places each vehicle on the map at each tick."""
    poses = {}
    actors = actor_of(root)
    for event in root.iter("Event"):
        entity = actors.get(id(event))
        for follow in event.iter("FollowTrajectoryAction"):
            vertices = [(float(v.get("time")),) + world_pose(v.find("Position")) for v in follow.iter("Vertex")]
            for (t0, x0, y0, h0), (t1, x1, y1, h1) in zip(vertices, vertices[1:]):
                for k in range(round(t0 / TICK), round(t1 / TICK) + 1):
                    f = (k * TICK - t0) / (t1 - t0)
                    turn = math.remainder(h1 - h0, 2 * math.pi)
                    poses[(entity, k)] = (x0 + f * (x1 - x0), y0 + f * (y1 - y0), h0 + f * turn)
            if len(vertices) == 1:
                t, x, y, h = vertices[0]
                poses[(entity, round(t / TICK))] = (x, y, h)
        begins = start_time(event)
        for teleport in event.iter("TeleportAction"):
            x, y, h = world_pose(teleport.find("Position"))
            inside = WORLD[0] <= x <= WORLD[2] and WORLD[1] <= y <= WORLD[3]
            if inside and begins is not None and begins > 0:
                # an event starts half a tick before the sample it places
                poses.setdefault((entity, round((begins + TICK / 2) / TICK)), (x, y, h))
    return poses


def declared_contacts(root):
    """[(frozenset of the two entities, seconds, event name)]: the contacts the file says sitcov's footprints had.

    Each is an event that waits for the two to touch, from half a tick before the last sample they were apart:
    they touched at the sample after it, a tick and a half after the event's time condition."""
    out = []
    for event in root.iter("Event"):
        collision = event.find("StartTrigger").find(".//CollisionCondition")
        if collision is not None:
            first = event.find(".//TriggeringEntities/EntityRef").get("entityRef")
            second = collision.find("EntityRef").get("entityRef")
            out.append((frozenset((first, second)), start_time(event) + 1.5 * TICK, event.get("name")))
    # a build that declares only the accidents, as parameters (accident<n>Other, accident<n>Time), compared with
    parameters = {p.get("name"): p.get("value") for p in root.iter("ParameterDeclaration")}
    for n in range(1, int(parameters.get("accidentCount", "0")) + 1):
        other = parameters["accident%d" % n + "Other"]
        if other != "none":
            out.append((frozenset(("ego", other)), float(parameters["accident%d" % n + "Time"]), None))
    return out


def events_started(log):
    """The names of the events esmini started."""
    return {m.group(1) for m in map(EVENT_STARTED.match, log) if m}


def esmini_collisions(log):
    """[(frozenset of the two entities, seconds it began, seconds it ended or None)] as esmini reported them."""
    out = []
    for line in log:
        m = COLLISION.match(line.strip())
        if not m:
            continue
        pair, t = frozenset((m.group(2), m.group(3))), float(m.group(1))
        if m.group(4):
            begun = next(i for i in reversed(range(len(out))) if out[i][0] == pair and out[i][2] is None)
            out[begun] = (pair, out[begun][1], t)
        else:
            out.append((pair, t, None))
    return out


def between_samples(began, ended):
    """Whether a contact began and ended between two of sitcov's samples, so that no tick's state had it."""
    return ended is not None and math.floor(began / TICK + 1e-6) == math.floor(ended / TICK - 1e-6)


def match(declared, reported):
    """(matched, esmini-only, file-only): a report matches an unmatched declaration of its pair within a tick."""
    left = sorted(((pair, t) for pair, t, _ in declared), key=lambda d: d[1])
    matched = 0
    only_esmini = []
    for pair, t, ended in sorted(reported, key=lambda r: r[1]):
        hit = next((d for d in left if d[0] == pair and abs(d[1] - t) <= TICK + 1e-6), None)
        if hit is None:
            only_esmini.append((sorted(pair), t, ended))
        else:
            left.remove(hit)
            matched += 1
    return matched, only_esmini, [(sorted(p), t) for p, t in left]


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, math.ceil(q * len(ordered)) - 1)] if ordered else float("nan")


def main(argv):
    each = "--each" in argv
    args = [a for a in argv if a != "--each"]
    if len(args) < 2:
        sys.exit(__doc__.strip().splitlines()[-1])
    esmini, folders = args[0], args[1:]
    files = sorted(os.path.join(d, f) for d in folders for f in os.listdir(d) if f.endswith(".xosc"))
    turns, offsets = [], []
    matched, only_esmini, only_file, with_ego, at_a_sample = 0, 0, 0, 0, 0
    events, fired = 0, 0
    routes, kept = 0, 0
    for xosc in files:
        root = ET.parse(xosc).getroot()
        recorded = root.find(".//FollowTrajectoryAction") is not None
        with tempfile.TemporaryDirectory() as work:
            # a situation is played only for its route, decided at the start: a coarse step is enough
            log, csv_path = play(esmini, xosc, work, STEP if recorded else 0.5)
            if not recorded:
                routes += 1
                dropped = any(ROUTE_DROPPED.search(line) for line in log)
                kept += 0 if dropped else 1
                if each:
                    print("%s: route %s" % (xosc, "dropped" if dropped else "kept"))
                continue
            played = esmini_poses(csv_path)
        file_turns = []
        for (entity, k), (x, y, h) in sitcov_poses(root).items():
            e = played.get((entity, round(k * TICK / STEP)))
            if e is None:
                continue
            file_turns.append(abs(math.degrees(math.remainder(e[2] - h, 2 * math.pi))))
            offsets.append(math.hypot(e[0] - x, e[1] - y))
        turns.extend(file_turns)
        declared = declared_contacts(root)
        m, e_only, f_only = match(declared, esmini_collisions(log))
        matched, only_esmini, only_file = matched + m, only_esmini + len(e_only), only_file + len(f_only)
        with_ego += sum(1 for pair, _, _ in e_only if "ego" in pair)
        at_a_sample += sum(1 for _, began, ended in e_only if not between_samples(began, ended))
        started = events_started(log)
        events, fired = events + len(declared), fired + sum(1 for d in declared if d[2] in started)
        if each:
            print("%s: heading max %.2f deg; collisions %d matched, esmini only %s, file only %s"
                  % (xosc, max(file_turns, default=0), m, e_only, f_only))
    print("recorded runs: %d ticks compared; |heading difference| max %.3f deg, 99th percentile %.3f deg;"
          " position max %.1f mm" % (len(turns), max(turns, default=float("nan")), percentile(turns, 0.99),
                                     1000 * max(offsets, default=float("nan"))))
    print("collisions: %d matched, %d esmini only (%d with the ego; %d not begun and ended between two samples),"
          " %d file only; %d of the file's %d contact events started"
          % (matched, only_esmini, with_ego, at_a_sample, only_file, fired, events))
    if routes:
        print("situations: ego route kept in %d of %d (%.0f %%)" % (kept, routes, 100.0 * kept / routes))


if __name__ == "__main__":
    main(sys.argv[1:])
