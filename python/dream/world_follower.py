"""Which world messages an agent host acts on: dream::lcm's WorldFollower (lcmtypes/lcm), in Python.

The host follows the run (run_id) it joined with its first DREAM_POSES, and within it takes
only the next step, a resend of the current one, or a short forward gap (lost datagrams in
real-time mode). A jump further away (or backwards) is taken only once the world confirms it
with the step after it, which a single forged datagram cannot do. Statuses and radio messages
of other runs are ignored; other runs seen are remembered (a second world on the same URL).
LCM has no authentication: this stops mistakes and blind forgeries, not a sender who copies
the run id and the next step from the bus.
"""

import logging

log = logging.getLogger("dream")

NEW_STEP, RESEND, IGNORE = "new_step", "resend", "ignore"
MAX_STEP_GAP = 30       # one second of Robotarium steps
MAX_OTHER_RUNS = 16     # so a flood of run ids cannot grow memory


def run_id_text(run_id):
    """16 hex digits, as the C++ side prints a run id."""
    return f"{run_id & 0xFFFFFFFFFFFFFFFF:016x}"


class WorldFollower:
    def __init__(self):
        self.run_id = 0
        self.step = -1
        self.other_runs = set()
        self.steps_out_of_sequence = 0
        self._unconfirmed_step = None

    @property
    def joined(self):
        return self.run_id != 0

    def _note_other_run(self, run_id):
        if len(self.other_runs) >= MAX_OTHER_RUNS or run_id in self.other_runs:
            return
        self.other_runs.add(run_id)
        log.error("another world (run %s) publishes on this LCM URL while this agent follows run %s: two "
                  "simulators (or a stale one) share the URL. Its messages are ignored; stop it or give each "
                  "run its own URL", run_id_text(run_id), run_id_text(self.run_id))

    def on_poses(self, run_id, step):
        """NEW_STEP, RESEND or IGNORE for a DREAM_POSES of `run_id` at `step`."""
        if run_id == 0 or step < 0:
            self.steps_out_of_sequence += 1
            return IGNORE
        if not self.joined:
            self.run_id, self.step = run_id, step
            return NEW_STEP
        if run_id != self.run_id:
            self._note_other_run(run_id)
            return IGNORE
        if step == self.step:
            return RESEND
        if step == self.step - 1:
            return IGNORE  # the world resent it before our answer reached it
        short_gap = self.step < step <= self.step + MAX_STEP_GAP
        confirmed = self._unconfirmed_step is not None and step == self._unconfirmed_step + 1
        if short_gap or confirmed:
            if confirmed and not short_gap:
                log.warning("run %s: the world moved from step %d to step %d; following it",
                            run_id_text(self.run_id), self.step, step)
            self.step = step
            self._unconfirmed_step = None
            return NEW_STEP
        self._unconfirmed_step = step
        self.steps_out_of_sequence += 1
        if self.steps_out_of_sequence == 1 or self.steps_out_of_sequence % 100 == 0:
            log.warning("DREAM_POSES: ignored step %d of run %s while at step %d (%d out of sequence so far)",
                        step, run_id_text(self.run_id), self.step, self.steps_out_of_sequence)
        return IGNORE

    def in_run(self, run_id):
        """Whether a status, obstacles or radio message of `run_id` is of the run followed."""
        if not self.joined:
            return False
        if run_id == self.run_id:
            return True
        self._note_other_run(run_id)
        return False

    def ends_run(self, run_id, step):
        """A FINISHED/ABORTED status ends the run only if of the run followed and not behind it."""
        return self.in_run(run_id) and step >= self.step
