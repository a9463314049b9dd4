"""The controller a script run's config names (`dream run SCRIPT.py` writes it): the robots of such
a run are driven by the script itself, one agent for all of them, never by this class. A config
of a script run given to `dream run CONFIG` gets its robots stopped with this message."""

from dream import Robot


class RobotariumScript(Robot):
    def update(self, step):
        raise RuntimeError("this run's robots were driven by a Robotarium script: rerun it with "
                           "`dream run SCRIPT.py` (its config.yaml names the script under description)")
