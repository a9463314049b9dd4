#!/usr/bin/python3
"""script_commands_log: a `dream run SCRIPT.py` run's log is the same whether the script sends every
robot's command in one DREAM_CMDS message (robot_commands_t, what DREAM's rps does) or one
DREAM_CMD_<id> per robot (the same script with its link's send() replaced by the per-robot one it
had before, lcm-gen's velocity_command_t): the world records each entry it takes as the DREAM_CMD_<id>
it stands for, so `dream log diff` of the two runs finds nothing, the batched run's log holds one
DREAM_CMD_<id> per robot and step and no DREAM_CMDS, and neither run refused a command.

Skipped (77) without numpy (DREAM's rps needs it).
Usage: netns.sh script_commands_log.py --dream BIN --source DIR --types-dir DIR
"""

import os

from dreamtest import check, main, read_events, read_summary, run_script, script_run_test_setup, tail

ROBOTS = 4
STEPS = 40

SCRIPT = """import numpy as np
import rps.robotarium as robotarium
{prelude}
r = robotarium.Robotarium(number_of_robots={robots}, show_figure=False, sim_in_real_time=False,
                          initial_conditions=np.array([[-0.6, -0.2, 0.2, 0.6], [0.0, 0.3, -0.3, 0.0],
                                                       [0.0, 1.0, -1.0, 3.0]]))
rng = np.random.default_rng(7)
for k in range({steps}):
    x = r.get_poses()
    r.set_velocities(np.arange({robots}), np.vstack([rng.uniform(-0.1, 0.1, {robots}),
                                                     rng.uniform(-1.0, 1.0, {robots})]))
    r.step()
r.call_at_scripts_end()
"""

# The link's send() as it was before DREAM_CMDS: one velocity_command_t per robot on DREAM_CMD_<id>.
PER_ROBOT = """import importlib
import rps._world_link as _link
from rps.utilities._dream_toolbox import dream_package


def _per_robot_send(self, velocities, done=False):
    command_t = importlib.import_module(dream_package().__name__ + ".velocity_command_t").velocity_command_t
    step = self._current
    speeds, turns = np.asarray(velocities, dtype=float)[:2, :self.n].tolist()
    self._answers = []
    for i, (v, w) in enumerate(zip(speeds, turns)):
        command = command_t()
        command.utime, command.step, command.run_id, command.robot_id = step.utime, step.step, step.run_id, i
        command.agent_id, command.v, command.w, command.done = self.agent_id, v, w, bool(done)
        self._answers.append(("DREAM_CMD_%d" % i, command.encode()))
    self.answered = True
    for channel, answer in self._answers:
        self.bus.publish(channel, answer)


_link.WorldLink.send = _per_robot_send
"""


def run_checked_script(ctx, args, name, prelude):
    script = ctx.path(name + ".py")
    with open(script, "w") as f:
        f.write(SCRIPT.format(prelude=prelude, robots=ROBOTS, steps=STEPS))
    out_dir, code, output = run_script(ctx, args.dream, script, name)
    check(code == 0, f"the {name} script's run exited {code}: {tail(output, 1500)}")
    summary = read_summary(out_dir)
    check(summary["steps"] == STEPS, f"the {name} run took {summary['steps']} steps, expected {STEPS}")
    check(summary["rejected_commands"] == 0 and summary["command_conflicts"] == 0,
          f"the {name} run refused commands: {summary['rejected_commands']} rejected, "
          f"{summary['command_conflicts']} conflicts; bad messages {summary.get('bad_messages')}")
    return out_dir


def commands_logged(dream, out_dir):
    by_channel = {}
    for event in read_events(os.path.join(out_dir, "run.lcmlog")):
        if event.channel.startswith("DREAM_CMD"):
            by_channel.setdefault(event.channel, []).append(event.data)
    check("DREAM_CMDS" not in by_channel, "DREAM_CMDS reached the run log")
    for channel, messages in by_channel.items():
        commands = [dream.velocity_command_t.decode(data) for data in messages]
        steps = [command.step for command in commands]
        # One per step() and then call_at_scripts_end()'s: the next step answered with every robot done.
        check(steps == list(range(STEPS + 1)), f"{channel}: commands logged for steps {steps[:5]}..{steps[-3:]}")
        done = [command.done for command in commands]
        check(done == [False] * STEPS + [True], f"{channel}: done flags {done[-3:]}")
    return sorted(by_channel)


def test(ctx):
    args, dream = script_run_test_setup()
    batched = run_checked_script(ctx, args, "batched", "")
    per_robot = run_checked_script(ctx, args, "per_robot", PER_ROBOT)
    channels = [f"DREAM_CMD_{i}" for i in range(ROBOTS)]
    check(commands_logged(dream, batched) == channels, f"the batched run logged {commands_logged(dream, batched)}")
    check(commands_logged(dream, per_robot) == channels, "the per-robot run's commands")
    code, out = ctx.run([args.dream, "log", "diff", batched, per_robot], timeout=60)
    check(code == 0, f"dream log diff of the batched and the per-robot run: exit {code}: {out[-800:]}")
    print(f"{ROBOTS} robots x {STEPS} steps: the batched and the per-robot run's logs equal (dream log diff), "
          "each command logged once as DREAM_CMD_<id>, none refused")


if __name__ == "__main__":
    main(test)
