import numpy as np

class Sensor:
    def __init__(self, robot_id, tag = 'Sensor'):
        """
        Sensor base class for a robot

        robot_id : int -> id of robot which it is attached
        tag       : str -> name tag of the sensor

        """

        self.robot_id = robot_id
        self.tag = tag

        self.pos_x = 0
        self.pos_y = 0
        self.rot_w = 0

        self.ret = 0    # return value

    def add_noise(self, values, noise):
        """
        Add random noise to the values measured

        Args:
            values : (np.array, list) -> values to be altered
            noise  : float             -> float value

        Return:
            np.array -> Same values altered by a random normal distribution
        """
        return np.add(values, np.random.normal(0, noise, np.shape(values)))

    def update(self, x):
        """
        Get current position of the sensor

        Args:
            x : np.array -> Positions of all robots
        """
        self.pos_x = x[0, self.robot_id]
        self.pos_y = x[1, self.robot_id]
        self.rot_w = x[2, self.robot_id]

class Movement_sensor(Sensor):
    def __init__(self, robot_id, tag, callback, range = 1.0, direction = 0.0, wide = 2*np.pi, noise = 0.0):
        """
        Movement sensor gets current position and velocity of all robots that can be detected

        robot_id : int          -> id of robot which it is attached
        tag       : str          -> name tag of the sensor
        callback  : callable     -> callback function
        range     : float        -> maximum distance of detection
        direction : float        -> counter-clockwise angle offset of the sensor respect the robot front
        wide      : float        -> aperture angle of the sensor
        noise     : float        -> noise of the sensor
        """

        self.callback = callback    # callback function

        self.range = range          # sensor maximum range
        self.direction = direction  # sensor pointing direction
        self.wide = wide / 2        # sensor aperture angle
        self.noise = noise          # sensor noise

        super().__init__(robot_id, tag)

    def update(self, x, v):
        """
        Get position and velocity of all other robot entities in range

        Args:
            x : np.array -> 3xN positions array of all robots
            v : np.array -> 2xN dynamics array of all robots from previous loop

        """

        super().update(x)

        self.ret = []

        for i in range(np.shape(x)[1]):

            dist = np.sqrt((self.pos_x - x[0, i])**2 + (self.pos_y - x[1, i])**2)
            angle = np.arctan2(self.pos_y - x[1, i], self.pos_x - x[0, i])

            angle_s = angle - (self.direction + self.rot_w) - np.pi
            angle_s = (angle_s + np.pi) % (2 * np.pi) - np.pi

            if dist > 0 and dist <= self.range and abs(angle_s) <= self.wide:

                cs = np.cos(x[2, i])
                ss = np.sin(x[2, i])

                vx = (cs*v[0, i] - 0.05*ss*v[1, i])
                vy = (ss*v[0, i] + 0.05*cs*v[1, i])

                self.ret.append([dist, angle, vx, vy])

        self.ret = self.add_noise(self.ret, self.noise)
        self.callback(self.ret)

class Odometry_sensor(Sensor):
    def __init__(self, robot_id, tag, callback, noise = 0.0):
        """
        Odometry sensor measures the current position of the attached robot

        robot_id : int          -> id of robot which it is attached
        tag       : str          -> name tag of the sensor
        callback  : callable     -> callback function
        noise     : float        -> noise of the sensor

        """

        self.callback = callback
        self.noise = noise

        super().__init__(robot_id, tag)

    def update(self, x):
        """
        Get current position of the robot attached

        Args:
            x : np.array-> 3xN positions array of all robot poses
        """

        super().update(x)

        self.ret = [self.pos_x, self.pos_y, self.rot_w]
        self.ret = self.add_noise(self.ret, self.noise)
        self.callback(self.ret)

if __name__ == "__main__":
    print("DREAM Sensor class")
