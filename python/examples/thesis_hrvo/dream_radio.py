import numpy as np

# Dictionary where all messages will be stored
messages = {}

class Radio:
    def __init__(self, robot_id, tag = 'Radio'):
        """
        Radio base class for a robot

        robot_id : int -> id of robot which it is attached
        tag       : str -> name tag of the radio

        """

        self.robot_id = robot_id
        self.tag = tag

        self.pos_x = 0
        self.pos_y = 0
        self.rot_w = 0

    def send_data(self, data) -> None:
        """
        Publish data in global dictionary of messages. Previous data is overwritten.

        Args:
            data : any -> values to be altered

        """
        messages[self.robot_id] = data

    def update(self, x):
        """
        Get current position of the radio

        Args:
            x : np.array -> Positions of all robots

        """

        self.pos_x = x[0, self.robot_id]
        self.pos_y = x[1, self.robot_id]
        self.rot_w = x[2, self.robot_id]

class Radio_range(Radio):
    def __init__(self, robot_id, tag, callback, range=1.0):
        """
        Radio gets current position and velocity of all robots that can be detected

        robot_id : int      -> id of robot which it is attached
        tag       : str      -> name tag of the sensor
        callback  : callable -> callback function
        range     : float    -> noise of the sensor
        """

        self.robot_id = robot_id
        self.tag = tag

        self.callback = callback
        self.range = range

        super().__init__(self.robot_id, self.tag)

    def update(self, x):
        """
        Get current position of the robot attached

        Args:
            x : np.array-> Positions of all robots
        """

        super().update(x)

        data_list = []
        for i in range(np.shape(x)[1]):

            if i in messages:
                dist = np.sqrt((self.pos_x - x[0, i])**2 + (self.pos_y - x[1, i])**2)

                if dist > 0 and dist <= self.range:
                    data_list.append(messages[i])

        robot_data = self.callback(data_list)
        self.send_data(robot_data)

if __name__ == "__main__":
    print("DREAM Radio class")
