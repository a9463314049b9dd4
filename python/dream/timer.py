"""The thesis's Timer without its global list (agents/src/timer.cc)."""


class Timer:
    """When each of a robot's parts runs, in steps of 0.033 s. Nothing runs while
    step <= start_delay_steps; after that a component with period p runs on every step where
    at least p steps have passed since it last ran (counting from step 0)."""

    __slots__ = ("start_delay_steps", "periods_steps", "_last_run_step", "_due")

    def __init__(self, start_delay_steps, periods_steps):
        if start_delay_steps < 0:
            raise ValueError(f"start_delay_steps must be >= 0, got {start_delay_steps}")
        for i, period in enumerate(periods_steps):
            if period < 1:
                raise ValueError(f"period of component {i} must be >= 1 step, got {period}")
        self.start_delay_steps = start_delay_steps
        self.periods_steps = list(periods_steps)
        self._last_run_step = [0] * len(self.periods_steps)
        self._due = [False] * len(self.periods_steps)

    def tick(self, step):
        """Which components run at `step`, in component order (a list reused between calls);
        call once per step with increasing steps."""
        started = step > self.start_delay_steps
        for i, period in enumerate(self.periods_steps):
            due = started and step - self._last_run_step[i] >= period
            self._due[i] = due
            if due:
                self._last_run_step[i] = step
        return self._due
