#!/usr/bin/env python3
"""Keeps its lane by two ground-truth channels; stops short of the next junction and at the Target."""
import math
from sitcov_client import serve

CHANNELS = ["lane_offset", "heading_error", "distance_to_junction", "target_distance"]


def step(obs):
    ch = obs["channels"]                              # null (None) where a channel has no value
    speed = min(1.5, ch["target_distance"] / 3.0)     # metres a tick; slows onto the Target
    if ch["distance_to_junction"] is not None:        # stops 2 m short of the next junction
        speed = min(speed, max(0.0, (ch["distance_to_junction"] - 2.0) / 4.0))
    offset, error = ch["lane_offset"] or 0.0, ch["heading_error"] or 0.0
    steering = math.degrees(math.atan2(offset, 6.0)) - error   # aims 6 m ahead at its lane centre
    return {"speed": speed, "steering": steering if speed > 0 else 0.0}


serve(step, name="minimal", channels=CHANNELS, sensors=[])
