"""
Robot values
"""
R_V_MAX      : float = 0.2      # max linear velocity
R_W_MAX      : float = 3.636363 # max angular velocity
R_AC_MAX     : float = 12.5     # max actuator velocity
R_R_WHEEL    : float = 0.016   # robot wheel radius
R_R_LENGTH   : float = 0.105   # robot length

"""
Terrain values
"""
T_WIDTH      : float = 3.2
T_HEIGHT     : float = 2.0
T_ORIGIN_X   : float = 0.0
T_ORIGIN_Y   : float = 0.0

T_MAX_WIDTH  = T_ORIGIN_X + T_WIDTH / 2
T_MIN_WIDTH  = T_ORIGIN_X - T_WIDTH / 2
T_MAX_HEIGHT = T_ORIGIN_Y + T_HEIGHT / 2
T_MIN_HEIGHT = T_ORIGIN_Y - T_HEIGHT / 2

if __name__ == '__main__':
    print("DREAM robot and terrain parameters")
