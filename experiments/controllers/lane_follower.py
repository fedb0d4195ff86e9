#!/usr/bin/env python3
"""A lane follower for sitcov's controller protocol (experiments/controllers/README.md, "Testing your own controller").

Standard library only. It drives from its sensors: the road-marking camera's hits (the kerb-side
edge line on its left, the centre line on its right; sitcov drives on the left) keep it in its
lane, the radar's traffic tracks and the LIDAR's obstacles (parked cars) stop it behind whatever
stands in its lane (it never overtakes), and it stops at the Target.
From the map it takes only where its road ends, to stop short of it. It knows nothing of junctions:
it drives straight on through them, and waits at the end of its road for ever (a TIMEOUT).

    python3 lane_follower.py          the example
    python3 lane_follower.py --bug    the same with a planted bug: above 1.2 m a tick it ignores
                                      the traffic ahead (a variant for the differential oracle)

The protocol (the handshake, the message loop, the tick echo) is sitcov_client.py's: this file is
the driving. It exits at the end of its input. Diagnostics go to stderr (sitcov keeps them in a log).
"""
import math
import sys

from sitcov_client import serve

CRUISE = 1.5          # metres a tick (27 km/h): modest
LOOKAHEAD = 6.0       # metres ahead it aims at its lane centre
CENTRE_LINE = 1.5     # metres from the lane centre to the centre line (on the right)
EDGE_LINE = 1.225     # metres from the lane centre to the edge line's middle (on the left)
BUGGY = "--bug" in sys.argv[1:]


def frame(heading):
    """Unit vectors ahead and to the right for a bearing (0 south, 90 east, 180 north, 270 west)."""
    b = math.radians(heading)
    return (math.sin(b), math.cos(b)), (-math.cos(b), math.sin(b))


def lane_offset(obs, ahead, right):
    """Metres from the car to its lane centre, positive to the right; None when no line is seen."""
    estimates = []
    for x, y in obs.get("camera", []):
        dx, dy = x - obs["x"], y - obs["y"]
        v = dx * right[0] + dy * right[1]
        estimates.append(v - CENTRE_LINE if v > 0 else v + EDGE_LINE)
    return sum(estimates) / len(estimates) if estimates else None


def room_to_road_end(obs, lane, roads):
    """Metres from the car's front to the end of the road it drives along, or None off every road."""
    x, y = obs["x"], obs["y"]
    for road in roads:
        along_y = road["axis"] == "north_south"
        if along_y != (lane % 180 == 0):
            continue
        across, along = (x, y) if along_y else (y, x)
        if abs(across - road["centre"]) <= 3 and road["from"] <= along <= road["to"]:
            # bearing 0 (south, +y) and 90 (east, +x) run towards "to"
            return road["to"] - along if lane % 360 in (0, 90) else along - road["from"]
    return None


def wanted_speed(obs, ahead, right, target, room):
    speed = CRUISE
    if room is not None:
        speed = min(speed, max(0.0, (room - 3.0) / 4.0))
    if not (BUGGY and obs["speed"] > 1.2):
        for car in obs["traffic"]:
            dx, dy = car["x"] - obs["x"], car["y"] - obs["y"]
            u = dx * ahead[0] + dy * ahead[1]
            v = dx * right[0] + dy * right[1]
            gap = u - car["length"]  # the track is its front: its tail is a length nearer
            if 0 < u < 40 and abs(v) < 1.8:
                speed = min(speed, max(0.0, (gap - 4.0) / 6.0))
    for box in obs["obstacles"]:
        dx, dy = box["x"] - obs["x"], box["y"] - obs["y"]
        u = dx * ahead[0] + dy * ahead[1]
        v = dx * right[0] + dy * right[1]
        if 0 < u < 40 and abs(v) < 1.8:
            speed = min(speed, max(0.0, (u - box["length"] / 2 - 3.0) / 6.0))
    tx, ty = target["x"] - obs["x"], target["y"] - obs["y"]
    along = tx * ahead[0] + ty * ahead[1]
    if -1 < along < 20 and abs(tx * right[0] + ty * right[1]) < 3:
        speed = min(speed, max(0.2, along / 5.0))
        if math.hypot(tx, ty) < 1.0:
            speed = 0.0
    return speed


def command(obs, target, roads):
    # the lane runs along the compass direction nearest the heading; lines are measured across it
    lane = round(obs["heading"] / 90.0) * 90.0
    ahead, right = frame(lane)
    offset = lane_offset(obs, ahead, right)
    aim = lane - math.degrees(math.atan2(offset if offset is not None else 0.0, LOOKAHEAD))
    turn = (aim - obs["heading"] + 180.0) % 360.0 - 180.0
    steering = max(-15.0, min(15.0, turn))
    room = room_to_road_end(obs, lane % 360, roads)
    wanted = wanted_speed(obs, ahead, right, target, room)
    change = max(-0.3, min(0.1, wanted - obs["speed"]))
    if obs["speed"] + change <= 0:
        steering = 0.0  # the car turns about its rear axle even standing: a stopped car holds the wheel
    return {"type": "command", "speed_change": change, "steering": steering}


def main():
    run = {"target": None, "roads": []}

    def reset(msg):
        run["target"], run["roads"] = msg["map"]["target"], msg["map"]["roads"]

    def ended(msg):
        print("run ended: %s after %d ticks" % (msg["outcome"], msg["ticks"]), file=sys.stderr)

    serve(lambda obs: command(obs, run["target"], run["roads"]), name="lane-follower" + ("-buggy" if BUGGY else ""),
          version="1", channels=[], sensors=["radar", "obstacles", "camera"], reset=reset, end=ended)


if __name__ == "__main__":
    main()
