"""A client for sitcov's controller protocol: write one function from observation to command.

Standard library only. serve() speaks the protocol on stdin and stdout (experiments/controllers/README.md, "Testing your own controller", "The protocol"): it answers sitcov's hello (protocol 2 when sitcov offers it, the
deprecated protocol 1 otherwise), hands each run's reset to an optional hook, answers every
observation with the command your function returns (adding "type" and, with protocol 2, the tick
of the observation it answers), hands each run's end to an optional hook, and returns at the end of
its input. Your function never writes to stdout: print diagnostics to stderr (sitcov keeps them in
a log).

A complete controller (experiments/controllers/minimal.py): it keeps its lane by two ground-truth
channels, and stops short of the next junction (it does not take junctions) and at the Target.

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

Run it with: java -jar target/sitcov-*.jar simulate --maps 20 --summary
    --controller "exec:python3 experiments/controllers/minimal.py"

The command your function returns is a dict with the members of the protocol's command:
"speed_change" (metres a tick, added to the speed) or "speed" (the speed itself), "steering"
(degrees, + towards larger bearings), and optionally "claim" and "release" (junction ids) and
"report". The observation is the protocol's observation as a dict, "tick" included.

Batches: serve(step, batch=B) tells sitcov it takes up to B runs in one message (sitcov's
'simulate --maps N --batch B'); step is still called once per observation, each of which then
carries "run" (its run's slot, 0..B-1; resets and ends carry it too), so keep any state per run.
A vectorised controller passes step_batch(observations) -> list of commands, in the same order,
instead of step. Without batch (or batch=1) nothing changes.
"""
import json
import sys

PROTOCOLS = (2, 1)   # the protocols this client speaks, the one it prefers first


def serve(step=None, name="controller", version="1", channels=(), sensors=("radar", "obstacles"),
          reset=None, end=None, stdin=None, stdout=None, batch=1, step_batch=None):
    """Serves a controller over the protocol until the end of the input.

    step(observation) -> command dict, called once for every observation.
    reset(message), optional: called with each run's reset (the map, "internal_seed", "faults").
    end(message), optional: called with each run's end ("outcome", "ticks").
    channels, sensors: what every observation should carry (experiments/controllers/README.md, "The protocol").
    batch: the most runs it takes in one message (1: one run at a time).
    step_batch(observations) -> list of command dicts, optional: answers a batch at once (else
    step is called for each observation); without step, it answers single observations too.
    """
    if step is None:
        if step_batch is None:
            raise ValueError("serve needs step or step_batch")
        step = lambda observation: step_batch([observation])[0]   # one run at a time: a batch of one
    stdin = sys.stdin if stdin is None else stdin
    stdout = sys.stdout if stdout is None else stdout
    protocol = None
    for line in stdin:
        msg = json.loads(line)
        kind = msg["type"]
        if kind == "hello":
            protocol = choose_protocol(msg)
            answer = {"type": "hello", "protocol": protocol, "name": name, "version": version,
                      "channels": list(channels), "sensors": list(sensors)}
            if batch > 1 and protocol >= 2:
                answer["batch"] = batch
        elif kind == "observation":
            answer = {"type": "command", "tick": msg["tick"]} if protocol >= 2 else {"type": "command"}
            answer.update(step(msg))
        elif kind == "observations":
            items = msg["items"]
            commands = step_batch(items) if step_batch is not None else [step(o) for o in items]
            answers = []
            for o, c in zip(items, commands):
                a = {"type": "command", "tick": o["tick"], "run": o["run"]}
                a.update(c)
                answers.append(a)
            answer = {"type": "commands", "items": answers}
        elif kind == "reset":
            if reset is not None:
                reset(msg)
            continue
        elif kind == "end":
            if end is not None:
                end(msg)
            continue
        else:
            continue   # a message of a later protocol: not for this client
        stdout.write(json.dumps(answer) + "\n")
        stdout.flush()


def choose_protocol(hello):
    """The newest protocol both sides speak: sitcov offers "protocols" (a sitcov of protocol 1 only
    names its one protocol in "protocol")."""
    offered = hello.get("protocols", [hello.get("protocol")])
    for p in PROTOCOLS:
        if p in offered:
            return p
    raise SystemExit("sitcov offers protocols %s; this client speaks %s" % (offered, list(PROTOCOLS)))
