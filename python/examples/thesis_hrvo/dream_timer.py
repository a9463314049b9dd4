import numpy as np

# List where all timers will be stored
timer_list = []

class Timer:
    def __init__(self, robot_id, timer_delay, list_of_timers):
        """
        Timer class to control when the different elements are to be activated

        robot_id      : int                -> id of robot which it is attached
        timer_delay    : int                -> number of steps until the robot is activated
        list_of_timers : list[dict{str, int | float | str | callable}] ->
                               list of timers in the form of [{'delay': int | float, 'tag': str, 'call': callable}, ...]
        """

        self.robot_id = robot_id          # id of robot which it is attached
        self.timer_delay = timer_delay    # robot start-up delay
        self.list_of_timers = [{'ptime': 0, 'delay': tim['delay'], 'tag': tim['tag'], 'call': tim['call']} for tim in list_of_timers]

        self.current_time = 0

    def update(self, current_time_, param):

        self.current_time = current_time_

        if self.current_time <= self.timer_delay:
            return

        for timer_ in self.list_of_timers:
            if self.current_time - timer_['ptime'] >= timer_['delay']:
                timer_['ptime'] = self.current_time
                timer_['call'](*param[timer_['tag']])

def update_timers(current_time, param) -> None:
    """
    Call this to update all timers

    Args:
        current_time -> current time of the simulation loop

    Return:
        None
    """

    for timer_unit in timer_list:
        timer_unit.update(current_time, param)

def create_timer(robot_id: int, delay: int, list_of_timers: list) -> Timer:
    """
    Call this to create a timer attached to a robot
    Timer created is stored in timer_list

    Args:
        robot_id : int -> Id of the robot to which it is attached
        delay      : int -> Number of iterations before starting
        list_of_timers : list[dict{str, int | float | str | callable}] ->
                            list of timers in the form of [{'delay': int | float, 'tag': str, 'call': callable}, ...]

    Return:
        Timer -> Timer created
    """

    # Create timer class and append to timer_list
    ti = Timer(robot_id, delay, list_of_timers)
    timer_list.append(ti)

    return ti

if __name__ == "__main__":
    print("DREAM Timer class")
