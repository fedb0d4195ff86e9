#!/usr/bin/env python3
"""A route-planning driver for sitcov's controller protocol (experiments/controllers/README.md, "Testing your own controller").

Standard library only. Where lane_follower.py only keeps its lane, this controller drives the
whole trip, as a controller someone would actually put under test:

* Route. From `reset` it builds the road graph (junctions as nodes, the straight stretches of road
  between them as edges) and plans the shortest way to the Target with Dijkstra, arriving in the
  lane the Target lies in (left-hand traffic: the Target is reached from the direction whose lane
  holds it). It re-plans whenever it enters a new stretch of road. A Target behind the car is
  reached by turning round in the next junction's square (a dead end's square or a T-junction's).
* Junctions. It slows on the approach, and a few metres before the square asks for the junction
  (`claim`) only when the signal says it would be given it (`would_grant`) and its exit lane is not
  blocked by a stopped vehicle; otherwise it stops 2.5 m short of the square and waits. It crosses
  on a planned path (straight on; a tight left turn round the kerb corner; a wide right turn; a
  U-turn on the spot in the square's middle), following it with its rear axle, which the car turns
  about. It lets go of the junction (`release`) once its footprint has left the square. A junction
  that follows right after the one it crosses is asked for while still crossing.
* Traffic. Radar tracks in the path ahead (its lane, or the crossing path) limit its speed so that
  it can stop behind them: a track's tail, its speed and the car's braking give the gap to keep.
  An oncoming car in its own lane makes it stop: a car standing still is never at fault.
* Parked cars. Obstacles (parked cars) standing in its lane make it stop some metres behind them.
  It pulls out into the other lane only when that lane is clear for the whole pass: no vehicle
  coming the other way could reach the pass before the car is back in its lane (their speed as
  reported, accelerating to the limit), and no car is parked in the other lane where it would pull
  out. It passes the whole row and pulls back in once its tail is clear; seeing a conflict before
  it reached the row it pulls back in and waits; beside the row it stops only for a car
  coming so near that going on would meet it.
* Target. On the Target's stretch it steers towards the Target's offset within its lane and slows
  so that it comes to rest on it; the run ends once its front centre is within 1.5 m.

What it senses (sensors asked for in its hello: radar, obstacles, camera; no ground-truth
channel): its pose and speed and the right-of-way signals from every observation; the road map
and the Target from the reset; the radar's traffic tracks; the parked cars as LIDAR obstacles;
the road-marking camera's hits. Where it is in its lane it works out from its pose on the road
map (the observation's pose is exact, so this is map localisation rather than sensing); on
straight road it takes the camera's reading instead (the centre line on its right and the
kerb-side edge line on its left, as lane_follower.py reads them, only when most hits agree) as
long as that lies within 0.4 m of the map's, which it does on most ticks away from junctions.
Passing, turning and at the Target it steers by the map alone.

It brakes and accelerates as a car can (0.1 m a tick faster, 0.16 slower a tick, 0.4 in an
emergency), although the world would carry out any speed from 0 to 2.5 m a tick at once.
It is deterministic: nothing in it is random (there was no choice `internal_seed` had to seed).

    python3 route_driver.py                    the controller
    python3 route_driver.py --bug blind-pass   planted bug: passing parked cars it judges the
                                               wrong lane: it looks for oncoming cars in its own
                                               lane, and while out in the other lane it keeps
                                               watching its own lane for traffic ahead
    python3 route_driver.py --bug late-brake   planted bug: following traffic it takes the
                                               vehicle ahead to keep its speed while the car
                                               brakes, and keeps no margin: it brakes too late
                                               when the vehicle ahead slows or stops

ROUTE_DRIVER_DEBUG=1 in its environment makes it write a line a tick on stderr (the stretch of
road, the route's next exits, the pass stage, the wanted and measured offset, the speed limit).

The protocol (the handshake, the message loop, the tick echo) is sitcov_client.py's: this file
is the driving. It exits at the end of its input. Diagnostics go to stderr (sitcov keeps them in
a log).
"""
import heapq
import math
import os
import sys

from sitcov_client import serve

DEBUG = os.environ.get("ROUTE_DRIVER_DEBUG") == "1"   # a line a tick on stderr: what limited the speed

# --- the world (roads 6 m, two 3 m lanes, junction squares 6 x 6 m, car 2 x 2 m) ---
HALF_ROAD = 3.0
LANE_CENTRE = 1.5            # lane centre, metres left of the road's centre line
HALF_SQUARE = 3.0
CAR_LENGTH = 2.0
CAR_HALF_WIDTH = 1.0
AXLE = 1.5                   # the rear axle, which the car turns about, is 1.5 m behind its front
MAX_SPEED = 2.5
MAX_TURN = 15.0
EDGE_LINE = 2.725            # the edge line's middle, metres from the centre line

# --- how it drives ---
CRUISE = 2.2                 # metres a tick (40 km/h)
ACCEL = 0.1                  # comfortable speed changes a tick
BRAKE = 0.16
HARD_BRAKE = 0.4             # an emergency stop (about 1 g)
APPROACH_LENGTH = 25.0       # slows for a junction from this far
APPROACH_SPEED = 1.8
ENTRY_SPEED = {"straight": 1.5, "right": 0.8, "left": 0.38, "uturn": 0.5}
WAIT_SHORT = 2.5             # waits this far short of a square it may not enter yet
EXIT_ROOM = 6.0              # room wanted beyond the square in the exit lane
EXIT_BEYOND = 1.5            # the crossing aims at a point this far beyond the square
TAIL = 4.0
LEFT_RADIUS = 1.5
RIGHT_RADIUS = 4.5
LOOK_BEYOND = 12.0           # while crossing, a junction whose square starts this near is asked for
TRAFFIC_MARGIN = 3.0         # gap kept to a vehicle ahead when stopped behind it
PARKED_WAIT_GAP = 5.0        # stops this far behind a parked car it cannot pass yet
PULL_OUT_AT = 8.0            # pulls out once the parked car's near end is this near its front
PASS_SPEED = 1.6
PASS_OFFSET = -0.9             # passes with its centre this far right of the centre line
PULL_IN_SPEED = 1.2
PULL_IN_BUFFER = 0.6         # pulls in once its tail is this far past the row
ROW_GAP = 16.0               # parked cars nearer than this along the lane are passed as one row
OVERTAKE_LOOK = 80.0

BUGS = ("blind-pass", "late-brake")


def unit(b):
    """Unit vector along a bearing (0 south = +y, 90 east = +x)."""
    r = math.radians(b)
    return math.sin(r), math.cos(r)


def left_of(b):
    """Unit vector to the left of a driver facing bearing b (steering + turns towards it)."""
    r = math.radians(b)
    return math.cos(r), -math.sin(r)


def wrap(a):
    """An angle in degrees brought into (-180, 180]."""
    a = (a + 180.0) % 360.0 - 180.0
    return 180.0 if a == -180.0 else a


def bearing_between(x0, y0, x1, y1):
    return math.degrees(math.atan2(x1 - x0, y1 - y0)) % 360.0


def box(cx, cy, b, length, width):
    """Corners of a box centred at (cx, cy) with its long side along bearing b."""
    ax, ay = unit(b)
    lx, ly = left_of(b)
    hl, hw = length / 2.0, width / 2.0
    return [(cx + ax * hl + lx * hw, cy + ay * hl + ly * hw), (cx + ax * hl - lx * hw, cy + ay * hl - ly * hw),
            (cx - ax * hl - lx * hw, cy - ay * hl - ly * hw), (cx - ax * hl + lx * hw, cy - ay * hl + ly * hw)]


def trailing_box(fx, fy, b, length, width):
    """Footprint of a vehicle whose front centre is (fx, fy), facing b."""
    ax, ay = unit(b)
    return box(fx - ax * length / 2.0, fy - ay * length / 2.0, b, length, width)


def overlap(p, q):
    """Separating-axis test of two convex quadrilaterals."""
    for poly in (p, q):
        for i in range(4):
            x0, y0 = poly[i]
            x1, y1 = poly[(i + 1) % 4]
            nx, ny = y0 - y1, x1 - x0
            a = [nx * x + ny * y for x, y in p]
            c = [nx * x + ny * y for x, y in q]
            if max(a) < min(c) or max(c) < min(a):
                return False
    return True


def stop_speed(distance, brake=BRAKE):
    """The fastest speed from which the car, moving this tick and braking after, stops within distance."""
    if distance <= 0:
        return 0.0
    return brake * (-1.0 + math.sqrt(1.0 + 2.0 * distance / brake))


def slow_speed(target, distance, brake=BRAKE):
    """The fastest speed from which the car can slow to `target` within distance."""
    return math.sqrt(target * target + 2.0 * brake * max(0.0, distance))


def turn_kind(arrival, exit_b):
    d = wrap(exit_b - arrival)
    if abs(d) < 1:
        return "straight"
    if abs(abs(d) - 180) < 1:
        return "uturn"
    return "left" if d > 0 else "right"


class RoadMap:
    """The map from the reset: roads, junctions, the graph between them, and the route planner."""

    def __init__(self, m):
        self.roads = {r["id"]: r for r in m["roads"]}
        self.junctions = {j["id"]: j for j in m["junctions"]}
        self.target = m["target"]
        # junctions along each road, ordered by their position along it
        self.along_road = {}
        for r in m["roads"]:
            ns = r["axis"] == "north_south"
            js = []
            for j in m["junctions"]:
                across, along = (j["x"], j["y"]) if ns else (j["y"], j["x"])
                if abs(across - r["centre"]) < 0.01 and r["from"] - 0.01 <= along <= r["to"] + 0.01:
                    js.append((along, j["id"]))
            js.sort()
            self.along_road[r["id"]] = js
        # neighbours: (junction, exit bearing) -> (next junction, road, length)
        self.next = {}
        for rid, js in self.along_road.items():
            ns = self.roads[rid]["axis"] == "north_south"
            up, down = (0.0, 180.0) if ns else (90.0, 270.0)  # bearings of growing and shrinking "along"
            for (a0, j0), (a1, j1) in zip(js, js[1:]):
                self.next[(j0, up)] = (j1, rid, a1 - a0)
                self.next[(j1, down)] = (j0, rid, a1 - a0)

    def road_bearings(self, rid):
        return (0.0, 180.0) if self.roads[rid]["axis"] == "north_south" else (90.0, 270.0)

    def along(self, rid, x, y):
        return y if self.roads[rid]["axis"] == "north_south" else x

    def across_left(self, rid, b, x, y):
        """Metres left of the road's centre line, for a driver facing b along road rid."""
        r = self.roads[rid]
        lx, ly = left_of(b)
        if r["axis"] == "north_south":
            return (x - r["centre"]) * lx
        return (y - r["centre"]) * ly

    def segment_at(self, x, y, b):
        """The stretch of road under (x, y) driven along lane bearing b: (road, junction behind, junction ahead)."""
        best = None
        for rid, r in self.roads.items():
            if b not in self.road_bearings(rid):
                continue
            ns = r["axis"] == "north_south"
            across, along = (x, y) if ns else (y, x)
            off = abs(across - r["centre"])
            if off > HALF_ROAD + 0.5 or not (r["from"] - 1.0 <= along <= r["to"] + 1.0):
                continue
            if best is None or off < best[0]:
                best = (off, rid)
        if best is None:
            return None
        rid = best[1]
        along = self.along(rid, x, y)
        forward = b in (0.0, 90.0)
        behind = ahead = None
        for a, j in self.along_road[rid]:   # ordered by growing "along"
            if forward:
                if a <= along:
                    behind = j
                elif ahead is None:
                    ahead = j
            else:
                if a < along:
                    ahead = j
                elif behind is None:
                    behind = j
        return rid, behind, ahead

    def target_reachable_from(self, rid, b):
        """Whether a car in the lane of bearing b on road rid can come within reach of the Target."""
        if rid != self.target["road"]:
            return False
        return self.across_left(rid, b, self.target["x"], self.target["y"]) >= -0.25

    def plan(self, rid, b, ahead, x, y, allow_here=True):
        """Exits to take, [(junction, exit bearing), ...], from a car on road rid facing b before junction ahead."""
        t = self.target
        if allow_here and self.target_reachable_from(rid, b) and t["road"] == rid:
            if (self.along(rid, t["x"], t["y"]) - self.along(rid, x, y)) * (1 if b in (0.0, 90.0) else -1) > -0.5:
                return []
        if ahead is None:
            return None
        start = (ahead, b)
        dist = {start: self.along_gap(rid, b, x, y, ahead)}
        prev = {}
        heap = [(dist[start], 0, start)]
        counter = 1
        best_goal, best_cost = None, math.inf
        while heap:
            cost, _, state = heapq.heappop(heap)
            if cost > dist.get(state, math.inf) or cost >= best_cost:
                continue
            j, arrived = state
            for e in (0.0, 90.0, 180.0, 270.0):
                nxt = self.next.get((j, e))
                if nxt is None:
                    continue
                k, road, length = nxt
                kind = turn_kind(arrived, e)
                turn_cost = {"straight": 0.0, "left": 3.0, "right": 5.0, "uturn": 30.0}[kind]
                if road == t["road"] and self.target_reachable_from(road, e):
                    jj = self.junctions[j]
                    to_target = (self.along(road, t["x"], t["y"]) - self.along(road, jj["x"], jj["y"])) \
                        * (1 if e in (0.0, 90.0) else -1)
                    if 0 <= to_target <= length + 0.5:
                        c = cost + turn_cost + to_target
                        if c < best_cost:
                            best_cost, best_goal = c, (state, e)
                c = cost + turn_cost + length
                ns = (k, e)
                if c < dist.get(ns, math.inf):
                    dist[ns] = c
                    prev[ns] = (state, e)
                    heapq.heappush(heap, (c, counter, ns))
                    counter += 1
        if best_goal is None:
            return None
        state, e = best_goal
        route = [(state[0], e)]
        while state in prev:
            state, e = prev[state]
            route.append((state[0], e))
        route.reverse()
        return route

    def along_gap(self, rid, b, x, y, j):
        jj = self.junctions[j]
        return abs(self.along(rid, jj["x"], jj["y"]) - self.along(rid, x, y))

    def distance_to_square(self, j, b, x, y):
        """Metres from (x, y) along bearing b to the near edge of junction j's square."""
        jj = self.junctions[j]
        ax, ay = unit(b)
        return (jj["x"] - x) * ax + (jj["y"] - y) * ay - HALF_SQUARE

    def square(self, j):
        jj = self.junctions[j]
        x, y = jj["x"], jj["y"]
        return [(x - 3, y - 3), (x + 3, y - 3), (x + 3, y + 3), (x - 3, y + 3)]


class CrossingPath:
    """A path for the rear axle through a junction square, as points with headings; U-turns turn on the spot."""

    def __init__(self, fx, fy, arrival, jx, jy, exit_b):
        ax, ay = unit(arrival)
        ex, ey = unit(exit_b)
        elx, ely = left_of(exit_b)
        # the front aims at the exit lane's centre just beyond the square
        wx = jx + ex * (HALF_SQUARE + EXIT_BEYOND) + elx * LANE_CENTRE
        wy = jy + ey * (HALF_SQUARE + EXIT_BEYOND) + ely * LANE_CENTRE
        self.exit_point = (wx, wy)
        self.exit_b = exit_b
        self.kind = turn_kind(arrival, exit_b)
        self.pts = []   # (x, y, heading, on_the_spot)
        px, py, h = fx - ax * AXLE, fy - ay * AXLE, arrival
        self.pts.append((px, py, h, False))
        endx, endy = wx - ex * AXLE, wy - ey * AXLE
        if self.kind == "straight":
            self._straight(endx, endy)
        elif self.kind == "uturn":
            rx, ry = -left_of(arrival)[0], -left_of(arrival)[1]
            # turn on the spot past the square's middle, half-way over the centre line
            tx, ty = jx + ax * 0.5 + rx * 0.75, jy + ay * 0.5 + ry * 0.75
            over = (px - tx) * ax + (py - ty) * ay
            if over > 0:
                tx, ty = tx + ax * over, ty + ay * over
            self._straight(tx, ty)
            to = bearing_between(tx, ty, endx, endy)
            turn = (self.pts[-1][2] - to) % 360.0   # turns right, towards the centre line
            steps = int(math.ceil(turn / MAX_TURN))
            h0 = self.pts[-1][2]
            for i in range(1, steps + 1):
                self.pts.append((tx, ty, (h0 - turn * i / steps) % 360.0, True))
            self._straight(endx, endy)
        else:
            left = self.kind == "left"
            # where the incoming and outgoing lane centres cross (for the axle, which follows the front's lane)
            if arrival in (0.0, 180.0):
                cx, cy = px, endy
            else:
                cx, cy = endx, py
            r = LEFT_RADIUS if left else RIGHT_RADIUS
            room = (cx - px) * ax + (cy - py) * ay
            r = max(1.0, min(r, room))
            sx, sy = cx - ax * r, cy - ay * r
            self._straight(sx, sy)
            ox, oy = sx + ex * r, sy + ey * r
            h0 = math.radians(arrival)
            sweep = math.pi / 2 if left else -math.pi / 2
            side = 1.0 if left else -1.0
            for i in range(1, 13):
                hh = h0 + sweep * i / 12
                qx = ox - math.sin(hh + side * math.pi / 2) * r
                qy = oy - math.cos(hh + side * math.pi / 2) * r
                self.pts.append((qx, qy, math.degrees(hh) % 360.0, False))
            self._straight(endx, endy)
        self._straight(wx + ex * (TAIL - AXLE), wy + ey * (TAIL - AXLE))
        self.progress = 0

    def _straight(self, x, y):
        x0, y0, h, _ = self.pts[-1]
        length = math.hypot(x - x0, y - y0)
        if length < 0.05:
            return
        d = bearing_between(x0, y0, x, y)
        if abs(wrap(d - h)) > 90:
            return
        n = max(1, int(math.ceil(length / 0.5)))
        for i in range(1, n + 1):
            self.pts.append((x0 + (x - x0) * i / n, y0 + (y - y0) * i / n, d, False))

    def turning_on_the_spot(self):
        return self.progress + 1 < len(self.pts) and self.pts[self.progress + 1][3]

    def steer_to(self, fx, fy, heading, speed):
        """The bearing to steer to (Stanley controller on the rear axle)."""
        hx, hy = unit(heading)
        px, py = fx - AXLE * hx, fy - AXLE * hy
        # finish turns on the spot that are done
        while self.turning_on_the_spot() and abs(wrap(heading - self.pts[self.progress + 1][2])) < 1.0:
            self.progress += 1
        if self.turning_on_the_spot():
            last = self.progress + 1
            while last + 1 < len(self.pts) and self.pts[last + 1][3]:
                last += 1
            return self.pts[self.progress + 1][2]
        best, nearest = math.inf, self.progress
        for i in range(self.progress, min(len(self.pts), self.progress + 16)):
            if i > self.progress and self.pts[i][3]:
                break
            d = (self.pts[i][0] - px) ** 2 + (self.pts[i][1] - py) ** 2
            if d < best:
                best, nearest = d, i
        self.progress = nearest
        ahead = min(nearest + 1, len(self.pts) - 1)
        planned = nearest if self.pts[ahead][3] else ahead
        h = self.pts[planned][2]
        ux, uy = unit(h)
        left = (px - self.pts[nearest][0]) * uy - (py - self.pts[nearest][1]) * ux
        return h - math.degrees(math.atan2(1.5 * left, speed + 1.0))

    def distance_to_spot_turn(self, fx, fy, heading):
        hx, hy = unit(heading)
        px, py = fx - AXLE * hx, fy - AXLE * hy
        for i in range(self.progress, len(self.pts) - 1):
            if self.pts[i + 1][3]:
                return math.hypot(self.pts[i][0] - px, self.pts[i][1] - py)
        return math.inf

    def finished(self):
        return self.progress >= len(self.pts) - 1

    def front_points_ahead(self, n=16):
        """Where the front will be along the path: the axle points moved forward by the axle distance."""
        out = []
        for x, y, h, _ in self.pts[self.progress:self.progress + n]:
            ux, uy = unit(h)
            out.append((x + AXLE * ux, y + AXLE * uy, h))
        return out


class Driver:
    def __init__(self, bug=None):
        self.bug = bug
        self.map = None

    # ---------------------------------------------------------------- reset
    def reset(self, msg):
        self.map = RoadMap(msg["map"])
        start = msg["map"]["start"]
        self.lane_b = round(start["heading"] / 90.0) * 90.0 % 360.0
        self.segment = None        # (road, junction behind, junction ahead)
        self.route = None
        self.mode = "lane"         # lane | crossing
        self.crossing_j = None
        self.path = None
        self.claimed = set()       # junctions it asked for and believes it holds
        self.next_claim = None     # a junction asked for while crossing the one before
        self.overtake = None       # None | "out" | "in"
        self.row_end = None        # along-lane position (in lane frame) of the row's far end
        self.last_speed = 0.0
        self.lane_offset_estimate = None
        self.camera_used = 0
        self.ticks = 0

    # ---------------------------------------------------------------- helpers
    def frame(self, obs):
        """Front position in the lane frame: (along the lane, metres left of the road's centre line)."""
        rid = self.segment[0]
        return (self.map.along(rid, obs["x"], obs["y"]) * (1 if self.lane_b in (0.0, 90.0) else -1),
                self.map.across_left(rid, self.lane_b, obs["x"], obs["y"]))

    def to_frame(self, x, y):
        rid = self.segment[0]
        return (self.map.along(rid, x, y) * (1 if self.lane_b in (0.0, 90.0) else -1),
                self.map.across_left(rid, self.lane_b, x, y))

    def footprint(self, obs):
        return trailing_box(obs["x"], obs["y"], obs["heading"], CAR_LENGTH, 2 * CAR_HALF_WIDTH)

    def locate(self, obs):
        seg = self.map.segment_at(obs["x"], obs["y"], self.lane_b)
        if seg is None:
            return
        if self.segment is None or seg != self.segment:
            self.segment = seg
            self.route = self.map.plan(seg[0], self.lane_b, seg[2], obs["x"], obs["y"])
            if self.route is None:
                print("tick %d: no route from road %d facing %g" % (obs["tick"], seg[0], self.lane_b), file=sys.stderr)

    def exit_at(self, j):
        if self.route and self.route[0][0] == j:
            return self.route[0][1]
        return self.exit_at_fallback(j, self.lane_b)

    def exit_at_fallback(self, j, b):
        """Off the plan: straight on where it can, else the first exit there is."""
        for e in (b, (b + 90) % 360, (b + 270) % 360, (b + 180) % 360):
            if (j, e) in self.map.next:
                return e
        return (b + 180) % 360

    def lane_camera_offset(self, obs):
        """Metres left of its lane centre by the camera, or None when the markings seen do not add up."""
        b = self.lane_b
        ax, ay = unit(b)
        lx, ly = left_of(b)
        ests = []
        for x, y in obs.get("camera") or ():
            dx, dy = x - obs["x"], y - obs["y"]
            u = dx * ax + dy * ay
            if u < 0.5:
                continue
            v = dx * lx + dy * ly   # left of the front
            # left-hand traffic: the edge line is on the left, the centre line on the right
            if v > 0:
                ests.append((EDGE_LINE - LANE_CENTRE) - v)
            elif v > -3.5:
                ests.append(-LANE_CENTRE - v)
        if len(ests) < 6:
            return None
        ests.sort()
        mid = ests[len(ests) // 2]
        close = [e for e in ests if abs(e - mid) < 0.15]
        if len(close) < 0.7 * len(ests):
            return None
        return sum(close) / len(close)

    # ---------------------------------------------------------------- traffic
    def tracks_in_lane(self, obs, s_lo, s_hi, my_along):
        """Nearest vehicle ahead whose footprint overlaps the lateral band [s_lo, s_hi]: (gap, its speed along the lane)."""
        best = (math.inf, 0.0)
        for t in obs.get("traffic", ()):
            corners = trailing_box(t["x"], t["y"], t["heading"], t["length"], t["width"])
            fr = [self.to_frame(x, y) for x, y in corners]
            lo = min(s for _, s in fr)
            hi = max(s for _, s in fr)
            if hi < s_lo or lo > s_hi:
                continue
            near = min(a for a, _ in fr) - my_along
            far = max(a for a, _ in fr) - my_along
            if far < 0.2:
                continue
            gap = max(0.0, near)
            along_speed = t["speed"] * math.cos(math.radians(wrap(t["heading"] - self.lane_b)))
            if gap < best[0]:
                best = (gap, along_speed)
        return best

    def follow_limit(self, gap, lead_speed):
        """Speed that keeps the car able to stop behind a vehicle `gap` ahead moving at lead_speed along the lane."""
        if self.bug == "late-brake":
            # planted bug: takes the vehicle ahead to keep its speed while the car brakes, so it
            # counts all the way the other would cover meanwhile as room, and keeps no margin
            stopping_ticks = self.last_speed / BRAKE + 1.0
            return stop_speed(gap - 0.5 + max(lead_speed, 0.0) * stopping_ticks)
        if lead_speed < -0.05:
            # coming towards it in its lane: stop, and early
            return stop_speed((gap - 4.0) / 2.0, HARD_BRAKE)
        lead_stop = lead_speed * lead_speed / (2 * 0.3)
        return stop_speed(gap - TRAFFIC_MARGIN + lead_stop, BRAKE)

    def path_blocked(self, obs, points):
        """Metres along the crossing path to the first point a vehicle stands on (or near), or inf."""
        boxes = []
        for t in obs.get("traffic", ()):
            if math.hypot(t["x"] - obs["x"], t["y"] - obs["y"]) < 20:
                boxes.append(trailing_box(t["x"], t["y"], t["heading"], t["length"] + 1.0, t["width"] + 1.0))
        if not boxes:
            return math.inf
        travelled = 0.0
        px, py = obs["x"], obs["y"]
        for x, y, h in points:
            travelled += math.hypot(x - px, y - py)
            px, py = x, y
            me = trailing_box(x, y, h, CAR_LENGTH, 2 * CAR_HALF_WIDTH)
            for bx in boxes:
                if overlap(me, bx):
                    return travelled
        return math.inf

    # ---------------------------------------------------------------- junctions
    def exit_clear(self, obs, j, exit_b):
        """No slow vehicle in the exit lane just beyond the square (it would block the car in the junction)."""
        jj = self.map.junctions[j]
        ex, ey = unit(exit_b)
        lx, ly = left_of(exit_b)
        for t in obs.get("traffic", ()):
            if t["speed"] >= 0.5:
                continue
            for x, y in trailing_box(t["x"], t["y"], t["heading"], t["length"], t["width"]):
                u = (x - jj["x"]) * ex + (y - jj["y"]) * ey
                v = (x - jj["x"]) * lx + (y - jj["y"]) * ly
                if HALF_SQUARE - 0.5 <= u <= HALF_SQUARE + EXIT_ROOM and 0 <= v <= HALF_ROAD + 0.2:
                    return False
        return True

    def signal(self, obs, j):
        for s in obs["junctions"]:
            if s["id"] == j:
                return s
        return {"holds": False, "would_grant": False}

    def try_claim(self, obs, j, exit_b, claims):
        """Asks for junction j when the signal would give it and the exit is clear; whether it holds it now."""
        sig = self.signal(obs, j)
        if sig["holds"]:
            return True
        if not self.exit_clear(obs, j, exit_b):
            return False
        if sig["would_grant"]:
            claims.append(j)
            self.claimed.add(j)
            return True
        return False

    # ---------------------------------------------------------------- each tick
    def step(self, obs):
        self.ticks += 1
        self.last_speed = obs["speed"]
        claims, releases = [], []
        # a junction held but taken over (held past another's patience) is no longer ours
        held_now = {s["id"] for s in obs["junctions"] if s["holds"]}
        self.claimed &= held_now
        for j in sorted(held_now - self.claimed):
            self.claimed.add(j)
        if self.mode == "crossing":
            speed, steer = self.cross(obs, claims)
        else:
            speed, steer = None, None
        if self.mode == "lane":
            speed, steer = self.drive_lane(obs, claims)
        # let go of every junction whose square it has left, unless it is the one it is about to cross
        me = self.footprint(obs)
        keep = set()
        if self.mode == "crossing":
            keep.add(self.crossing_j)
        if self.next_claim is not None:
            keep.add(self.next_claim)
        if self.mode == "lane" and self.segment and self.segment[2] is not None:
            keep.add(self.segment[2])
        for j in sorted(self.claimed):
            if j not in keep and not overlap(me, self.map.square(j)):
                releases.append(j)
        for j in releases:
            self.claimed.discard(j)
        # comfortable speed changes; hard braking only when needed
        v = obs["speed"]
        if speed > v:
            speed = min(speed, v + ACCEL)
        else:
            speed = max(speed, v - HARD_BRAKE)
        speed = max(0.0, min(MAX_SPEED, speed))
        steer = max(-MAX_TURN, min(MAX_TURN, steer))
        cmd = {"type": "command", "speed": speed, "steering": steer}
        if releases:
            cmd["release"] = releases
        if claims:
            cmd["claim"] = claims
        cmd["report"] = {"crossing_junction": self.mode == "crossing", "overtaking": self.overtake is not None,
                         "stage": self.mode if self.overtake is None else "overtake-" + self.overtake}
        return cmd

    # ---------------------------------------------------------------- lane driving
    def drive_lane(self, obs, claims):
        self.locate(obs)
        if self.segment is None:
            # off every road it knows: stop and hold the wheel
            return 0.0, 0.0
        rid, behind, ahead = self.segment
        my_along, my_s = self.frame(obs)
        limit = CRUISE
        want_s = LANE_CENTRE

        # --- the Target
        t = self.map.target
        target_here = (self.route == [] and rid == t["road"])
        if target_here:
            ta, ts = self.to_frame(t["x"], t["y"])
            to_go = ta - my_along
            if to_go < -1.5 and self.overtake is None:
                # driven past it (it lay beside a parked car, say): plan the way round again
                self.route = self.map.plan(rid, self.lane_b, ahead, obs["x"], obs["y"], allow_here=False)
                target_here = False
            else:
                if to_go < 15:
                    # within its lane, as near the Target's offset as the lane's lines allow
                    want_s = max(1.15, min(1.8, ts))
                limit = min(limit, max(0.3, stop_speed(to_go + 0.3)))
                if abs(want_s - my_s) > 0.5 and self.overtake != "out":
                    limit = min(limit, max(0.3, stop_speed(to_go - 1.0)))
        if self.route is None and ahead is None:
            return 0.0, 0.0    # lost (beyond the last junction of its road): stand still

        # --- junction ahead
        if ahead is not None and not target_here:
            limit = min(limit, self.approach_junction(obs, ahead, claims))
            if self.mode == "crossing":
                return self.cross(obs, claims)

        # --- parked cars and traffic
        want_s, limit = self.parked_cars(obs, my_along, my_s, want_s, limit)
        band_lo, band_hi = min(want_s, my_s) - CAR_HALF_WIDTH - 0.2, max(want_s, my_s) + CAR_HALF_WIDTH + 0.2
        if self.bug == "blind-pass":
            # planted bug: out in the other lane it keeps watching its own lane for traffic
            band_lo, band_hi = LANE_CENTRE - CAR_HALF_WIDTH - 0.2, LANE_CENTRE + CAR_HALF_WIDTH + 0.2
        gap, lead = self.tracks_in_lane(obs, band_lo, band_hi, my_along)
        if gap < math.inf:
            limit = min(limit, self.follow_limit(gap, lead))

        if DEBUG:
            print("t%d seg%s route%s ov=%s want_s=%.2f my_s=%.2f along=%.1f gap=%.1f lead=%.2f limit=%.2f"
                  % (obs["tick"], self.segment, self.route[:2] if self.route else self.route, self.overtake,
                     want_s, my_s, my_along, gap, lead, limit), file=sys.stderr)
        # --- steering: towards the wanted offset in the lane
        cam = self.lane_camera_offset(obs) if self.overtake is None else None
        s_est = my_s
        if cam is not None and abs((LANE_CENTRE + cam) - my_s) < 0.4:
            s_est = LANE_CENTRE + cam
            self.camera_used += 1
        if self.overtake is None:
            look = max(4.0, 2.5 * obs["speed"] + 3.0)
        else:
            # pulling out or in is a swerve that must be done within a few metres (the centre line
            # is excused only near the parked car): look nearer, and allow up to 40 degrees
            look = max(1.0, 1.5 * obs["speed"] + 1.0)
        bound = 40.0
        if self.overtake == "squeeze":
            look, bound = 1.0, 50.0
        aim = self.lane_b + math.degrees(math.atan2(want_s - s_est, look))
        aim = self.lane_b + max(-bound, min(bound, wrap(aim - self.lane_b)))
        steer = wrap(aim - obs["heading"])
        if limit <= 0.05 and obs["speed"] <= HARD_BRAKE and self.overtake != "squeeze":
            steer = 0.0   # standing (or about to): hold the wheel, turning on the spot swings the front about
        return limit, steer

    def approach_junction(self, obs, j, claims):
        """Speed limit for the junction ahead; starts crossing it when the car is at its square and holds it."""
        d = self.map.distance_to_square(j, self.lane_b, obs["x"], obs["y"])
        if d > APPROACH_LENGTH:
            return CRUISE
        exit_b = self.exit_at(j)
        kind = turn_kind(self.lane_b, exit_b)
        limit = slow_speed(APPROACH_SPEED, d - 2)
        holds = j in self.claimed
        if not holds and d <= stop_speed_distance(obs["speed"]) + WAIT_SHORT + 3.0:
            holds = self.try_claim(obs, j, exit_b, claims)
        if holds:
            if d <= 0.05:
                self.start_crossing(obs, j, exit_b)
                return ENTRY_SPEED[kind]
            return min(limit, slow_speed(ENTRY_SPEED[kind], d))
        return min(limit, stop_speed(d - WAIT_SHORT))

    def start_crossing(self, obs, j, exit_b):
        jj = self.map.junctions[j]
        self.mode = "crossing"
        self.crossing_j = j
        self.path = CrossingPath(obs["x"], obs["y"], self.lane_b, jj["x"], jj["y"], exit_b)
        self.overtake = None
        if self.next_claim == j:
            self.next_claim = None

    def cross(self, obs, claims):
        p = self.path
        kind = p.kind
        ex, ey = unit(p.exit_b)
        beyond = (obs["x"] - p.exit_point[0]) * ex + (obs["y"] - p.exit_point[1]) * ey
        # the junction after this one, on the exit road
        nxt = self.map.next.get((self.crossing_j, p.exit_b))
        finish = 2.0
        if nxt is not None:
            dn = self.map.distance_to_square(nxt[0], p.exit_b, p.exit_point[0], p.exit_point[1])
            if dn < TAIL / 2 + 1:
                finish = 0.0
        jj = self.map.junctions[self.crossing_j]
        strayed = math.hypot(obs["x"] - jj["x"], obs["y"] - jj["y"]) > 12
        if beyond > finish or p.finished() or strayed:
            self.mode = "lane"
            self.lane_b = p.exit_b
            self.segment = None
            self.path = None
            self.locate(obs)
            return None, None
        limit = ENTRY_SPEED[kind]
        steer_to = p.steer_to(obs["x"], obs["y"], obs["heading"], obs["speed"])
        if p.turning_on_the_spot():
            return 0.0, wrap(steer_to - obs["heading"])
        limit = min(limit, stop_speed(p.distance_to_spot_turn(obs["x"], obs["y"], obs["heading"])))
        # vehicles on the path ahead
        blocked = self.path_blocked(obs, p.front_points_ahead())
        if blocked < math.inf:
            limit = min(limit, stop_speed(blocked - 1.0, HARD_BRAKE))
        # the next junction, when it follows close behind this one: ask for it now
        if nxt is not None:
            k = nxt[0]
            dk = self.map.distance_to_square(k, p.exit_b, obs["x"], obs["y"])
            if dk < LOOK_BEYOND and k not in self.claimed:
                exit_k = self.exit_after(k, p.exit_b)
                if self.try_claim(obs, k, exit_k, claims):
                    self.next_claim = k
                else:
                    limit = min(limit, stop_speed(dk - 0.3, HARD_BRAKE))
        return limit, wrap(steer_to - obs["heading"])

    def exit_after(self, k, arriving_b):
        """The exit planned at junction k, reached facing arriving_b after this crossing."""
        if self.route and len(self.route) > 1 and self.route[0][0] == self.crossing_j and self.route[1][0] == k:
            return self.route[1][1]
        return self.exit_at_fallback(k, arriving_b)

    # ---------------------------------------------------------------- parked cars
    def parked_cars(self, obs, my_along, my_s, want_s, limit):
        """Stops behind parked cars in its lane, or passes them in the other lane when it is clear."""
        mine = []    # (near, far) along-lane extents of parked cars standing in its lane
        other_lane = []
        for o in obs.get("obstacles", ()):
            if abs(self.map.across_left(self.segment[0], self.lane_b, o["x"], o["y"])) > HALF_ROAD + 1:
                continue   # on another road
            fr = [self.to_frame(x, y) for x, y in box(o["x"], o["y"], o["bearing"], o["length"], o["width"])]
            lo, hi = min(s for _, s in fr), max(s for _, s in fr)
            near, far = min(a for a, _ in fr), max(a for a, _ in fr)
            if far < my_along - CAR_LENGTH - 3 or near > my_along + OVERTAKE_LOOK:
                continue
            if hi > 0.3 and lo < HALF_ROAD:
                mine.append((near, far))
            elif lo < -0.3 and hi > -HALF_ROAD:
                other_lane.append((near, far))
        mine.sort()
        t = self.map.target
        target_ta = None
        if self.route == [] and self.segment[0] == t["road"]:
            target_ta, _ = self.to_frame(t["x"], t["y"])
            # parked cars beyond the Target do not matter: the run ends there
            mine = [m for m in mine if m[0] < target_ta]
        # rows: cars closer than ROW_GAP one after another are passed in one go
        rows = []
        for near, far in mine:
            if rows and near - rows[-1][1] < ROW_GAP and not any(
                    f > rows[-1][1] - 1 and n < near + 1 for n, f in other_lane):
                # (a car parked in the other lane in the gap splits the row: it pulls in between)
                rows[-1][1] = max(rows[-1][1], far)
            else:
                rows.append([near, far])
        # the row it is passing or will pass next: the first its tail is not yet clear of
        rows = [r for r in rows if r[1] + PULL_IN_BUFFER >= my_along - CAR_LENGTH]
        row = rows[0] if rows else None
        if self.overtake == "out":
            squeeze = target_ta is not None and row is not None and row[1] < target_ta < row[1] + 8.0
            if squeeze and my_along > row[1] + 1.7:
                # the Target just past the row: squeeze in at it once the front is past the row
                # (turning about its rear axle, the car's tail swings away from the parked car)
                self.overtake = "squeeze"
            elif row is None or row[0] > self.row_end + 0.5:
                self.overtake = "in"     # its tail is clear of the row it passed
            else:
                self.row_end = row[1]
                if self.oncoming_conflict(obs, my_along, row, [], committed=my_along >= row[0] - 1.0):
                    if my_along < row[0] - 1.0 and my_s > -0.3:
                        # not yet beside the row: go back to its lane and wait
                        self.overtake = None
                        return LANE_CENTRE, min(limit, stop_speed(row[0] - my_along - 1.5, HARD_BRAKE))
                    # beside the row: stand still until the other car has passed or given up
                    return PASS_OFFSET, 0.0
                if squeeze:
                    limit = min(limit, max(0.3, stop_speed(row[1] + 1.8 - my_along)))
                return PASS_OFFSET, min(limit, PASS_SPEED, self.pull_out_speed(my_along, my_s, row))
        if self.overtake == "squeeze":
            if target_ta is None or target_ta < my_along - 1.5:
                self.overtake = None
            # turn (on the spot) first, then creep towards it
            if abs(want_s - my_s) > 0.6 and abs(wrap(obs["heading"] - self.lane_b)) < 25:
                return want_s, 0.0
            return want_s, min(limit, 0.3)
        if self.overtake == "in":
            if row is None or row[0] - my_along > PULL_OUT_AT:
                if abs(my_s - LANE_CENTRE) < 0.3:
                    self.overtake = None
                speed = PULL_IN_SPEED
                if any(far > my_along - CAR_LENGTH and near < my_along + 8.0 for near, far in other_lane):
                    # a car parked in the other lane just after the row: pull in slowly, so the
                    # car's body swings in before it comes up to it
                    speed = 0.5
                return want_s, min(limit, speed)
            self.overtake = None     # another row right after: decide again below
        if row is None:
            return want_s, limit
        gap = row[0] - my_along
        if target_ta is not None and my_along - 1 < target_ta < row[0] - 1.0:
            return want_s, limit   # the Target comes before the row
        if gap < PULL_OUT_AT and not self.oncoming_conflict(obs, my_along, row, other_lane):
            self.overtake = "out"
            self.row_end = row[1]
            return PASS_OFFSET, min(limit, PASS_SPEED, self.pull_out_speed(my_along, my_s, row))
        return want_s, min(limit, stop_speed(gap - PARKED_WAIT_GAP))

    @staticmethod
    def pull_out_speed(my_along, my_s, row):
        """Slow enough to be clear of the row sideways before the front comes up to it."""
        sideways = my_s - (PASS_OFFSET + 0.4)
        room = row[0] - my_along - 0.3
        if sideways > 0 and room < sideways / 0.8 + 1.5:
            return 0.2     # turning about the rear axle does most of the swerve
        return MAX_SPEED

    def oncoming_conflict(self, obs, my_along, row, other_lane, committed=False):
        """Whether the other lane is not clear for a pass of the row and back into its lane.

        Committed (beside the row already), it asks only whether a vehicle coming the other way is
        so near that it must stand still for it: going on at pass speed is then the quicker way out."""
        pass_length = max(0.0, row[1] - my_along) + CAR_LENGTH + PULL_IN_BUFFER + 7.0
        ticks = pass_length / PASS_SPEED + 6
        if committed:
            ticks = 4
        for near, far in other_lane:
            if far > max(my_along - CAR_LENGTH, row[0] - 4.0) and near < row[1] + 2.0:
                return True   # a car parked in the other lane where it would drive out there
        for t in obs.get("traffic", ()):
            ta, ts = self.to_frame(t["x"], t["y"])
            rel = wrap(t["heading"] - self.lane_b)
            if abs(rel) < 45 and ts > 0:
                continue   # going its way in its own lane: that is following, not passing
            if abs(rel) < 45 and ta > my_along:
                continue   # going its way ahead in the other lane: moving away
            if abs(ts) > 12:
                continue   # far off to the side of this road
            if self.bug == "blind-pass" and ts < 0:
                continue   # planted bug: it looks for oncoming cars in its own lane, not the other
            if True:
                v, reach = t["speed"], 0.0
                for _ in range(int(ticks) + 1):
                    v = min(MAX_SPEED, v + 0.1)
                    reach += v
                horizon = pass_length + reach + 8.0
            # the other car's tail counts when it comes from behind
            if -t["length"] - 3.0 < ta - my_along < horizon:
                return True
        return False


def stop_speed_distance(v, brake=BRAKE):
    """Distance to stop from speed v braking comfortably (moving this tick first)."""
    return v + v * v / (2 * brake)


def main():
    bug = None
    args = sys.argv[1:]
    if "--bug" in args:
        i = args.index("--bug")
        bug = args[i + 1] if i + 1 < len(args) else ""
        if bug not in BUGS:
            print("unknown bug %r; the bugs are %s" % (bug, ", ".join(BUGS)), file=sys.stderr)
            sys.exit(2)
    driver = Driver(bug)

    def ended(msg):
        print("run ended: %s after %d ticks (camera steered %d ticks)"
              % (msg["outcome"], msg["ticks"], driver.camera_used if driver.map else 0), file=sys.stderr)

    serve(driver.step, name="route-driver" + ("-" + bug if bug else ""), version="1", channels=[],
          sensors=["radar", "obstacles", "camera"], reset=driver.reset, end=ended)


if __name__ == "__main__":
    main()
