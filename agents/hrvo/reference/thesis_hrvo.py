#!/usr/bin/env python3
"""The thesis's Robot_hrvo.HRVO (Appendix A.1) and the movement sensor's
detection (Appendix A.2), transcribed line by line with numpy, to produce
known answers for tests/agents/hrvo_test.cc (HrvoThesis must match them).

Run: /usr/bin/python3 agents/hrvo/reference/thesis_hrvo.py > cases.inc
(C++ initialisers, pasted into MatchesTheThesisCodeOnKnownAnswers).
"""
import numpy as np

V_MAX = 0.2
BOUND_X = [-1.6, 1.6]
BOUND_Y = [-1.0, 1.0]


def detect(self_xy, other_xy, other_pose_theta, other_v, other_w):
    """Movement_sensor.update for one neighbour: [dist, angle, vx, vy]."""
    dist = np.sqrt((self_xy[0] - other_xy[0])**2 + (self_xy[1] - other_xy[1])**2)
    angle = np.arctan2(self_xy[1] - other_xy[1], self_xy[0] - other_xy[0])
    cs = np.cos(other_pose_theta)
    ss = np.sin(other_pose_theta)
    vx = (cs*other_v - 0.05*ss*other_w)
    vy = (ss*other_v + 0.05*cs*other_w)
    return [dist, angle, vx, vy]


def hrvo(pos, dxi, detections, desired_velocity, safety=0.24, check_boundaries=True):
    """Robot_hrvo.HRVO; returns the new self.dxi."""
    detections = np.asarray(detections)
    n_detections = len(detections)
    hrvo_mat = np.empty((n_detections * 2, 2))
    hrvo_vec = np.empty((n_detections * 2))
    for i in range(n_detections):
        obst_dist = detections[i, 0]
        obst_angl = detections[i, 1]
        obst_velx = detections[i, 2]
        obst_vely = detections[i, 3]
        obst_dist = obst_dist if obst_dist > safety else safety
        obst_phi = np.arcsin(safety / obst_dist)
        obst_phi_l = obst_angl + obst_phi
        obst_phi_r = obst_angl - obst_phi
        temp_mat_ = np.array([[1., 0., 0.], [0., 1., 0.], [-obst_velx, -obst_vely, 1.]])
        temp_lin_l = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_l), np.sin(obst_phi_l)]))
        temp_lin_l = temp_mat_ @ temp_lin_l
        hrvo_mat[i*2, :] = -temp_lin_l[:2]
        hrvo_vec[i*2] = temp_lin_l[2]
        temp_lin_r = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_r), np.sin(obst_phi_r)]))
        temp_lin_r = temp_mat_ @ temp_lin_r
        hrvo_mat[i*2 + 1, :] = temp_lin_r[:2]
        hrvo_vec[i*2 + 1] = -temp_lin_r[2]
        # RVO
        temp_mat_ = np.array([[1., 0., 0.], [0., 1., 0.], [-(obst_velx+dxi[0])/2, -(obst_vely+dxi[1])/2, 1.]])
        # HRVO
        temp_lin_l = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_l), np.sin(obst_phi_l)]))
        temp_lin_l = temp_mat_ @ temp_lin_l
        dist_l = abs(temp_lin_l[0]*dxi[0]+temp_lin_l[1]*dxi[1]+temp_lin_l[2])/np.sqrt(temp_lin_l[0]**2 + temp_lin_l[1]**2)
        temp_lin_r = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_r), np.sin(obst_phi_r)]))
        temp_lin_r = temp_mat_ @ temp_lin_r
        dist_r = abs(temp_lin_r[0]*dxi[0]+temp_lin_r[1]*dxi[1]+temp_lin_r[2])/np.sqrt(temp_lin_r[0]**2 + temp_lin_r[1]**2)
        if dist_l < dist_r:
            hrvo_mat[i*2, :] = -temp_lin_l[:2]
            hrvo_vec[i*2] = temp_lin_l[2]
        if dist_l > dist_r:
            hrvo_mat[i*2 + 1, :] = temp_lin_r[:2]
            hrvo_vec[i*2 + 1] = -temp_lin_r[2]
    th = np.linspace(0, 2 * np.pi, 20)
    vel = np.linspace(0.0, V_MAX, 10)
    vv, thth = np.meshgrid(vel, th)
    vx_sample = np.append((vv * np.cos(thth)).flatten(), 0)
    vy_sample = np.append((vv * np.sin(thth)).flatten(), 0)
    v_sample = np.stack((vx_sample, vy_sample))
    for i in range(n_detections):
        hrvo_mat_ = hrvo_mat[2*i:2*i+2, :]
        hrvo_vec_ = hrvo_vec[2*i:2*i+2]
        v_out = []
        for i in range(np.shape(v_sample)[1]):
            if not ((hrvo_mat_ @ v_sample[:, i] < hrvo_vec_).all()):
                v_out.append(v_sample[:, i])
        v_sample = np.array(v_out).T
    if np.shape(v_sample)[0] == 0:
        v_sample = np.array([[0.0], [0.0]])
    if check_boundaries:
        v_out = []
        for i in range(np.shape(v_sample)[1]):
            if BOUND_X[0] < v_sample[0, i] + pos[0] < BOUND_X[1] and BOUND_Y[0] < v_sample[1, i] + pos[1] < BOUND_Y[1]:
                v_out.append(v_sample[:, i])
        v_sample = np.array(v_out).T
        if np.shape(v_sample)[0] == 0:
            v_sample = np.array([[0.0], [0.0]])
    size = np.shape(v_sample)[1]
    diffs = v_sample - ((desired_velocity).reshape(2, 1) @ np.ones(size).reshape(1, size))
    norm = np.linalg.norm(diffs, axis=0)
    min_index = np.where(norm == np.amin(norm))[0][0]
    out = (v_sample[:, min_index]).copy()
    limit_norm = np.linalg.norm(out)
    if limit_norm > V_MAX:
        out *= V_MAX/limit_norm
    return out


def cpp_case(pos, dxi, desired, nbrs, comment=None):
    """Prints one case as a C++ initialiser for tests/agents/hrvo_test.cc:
    {pos, dxi, desired, {{rel, vel}...}, expected}; nbrs are (x, y, theta, v, w)
    world poses and commands of the neighbours, seen by the movement sensor."""
    pos = np.asarray(pos, float)
    dets = [detect(pos, (n[0], n[1]), n[2], n[3], n[4]) for n in nbrs]
    out = hrvo(pos, np.asarray(dxi, float), dets, np.asarray(desired, float))
    ns = ", ".join(f"{{{{{n[0] - pos[0]!r}, {n[1] - pos[1]!r}}}, {{{d[2]!r}, {d[3]!r}}}}}"
                   for n, d in zip(nbrs, dets))
    if comment:
        print(f"      // {comment}")
    print(f"      {{{{{pos[0]!r}, {pos[1]!r}}}, {{{dxi[0]!r}, {dxi[1]!r}}}, "
          f"{{{desired[0]!r}, {desired[1]!r}}}, {{{ns}}}, {{{out[0]!r}, {out[1]!r}}}}},")


def hand_made_cases():
    # Exactly mirror-symmetric situations are left out: numpy breaks their
    # ties by the last bit of its own sin/cos (see docs/hrvo.md).
    cpp_case((0.0, 0.0), (0.0, 0.0), (0.2, 0.0), [(0.5, 0.0, np.pi, 0.0, 0.0)], "static neighbour ahead")
    cpp_case((-0.5, 0.0), (0.2, 0.01), (0.2, 0.0), [(0.5, 0.03, np.pi, 0.16, 0.0)], "head-on at speed")
    cpp_case((-0.5, 0.0), (0.15, 0.05), (0.2, 0.0), [(0.3, 0.02, np.pi, 0.16, 0.0)], "head-on, offset")
    cpp_case((0.0, 0.0), (0.2, 0.0), (0.2, 0.0), [(-0.5, 0.0, 0.0, 0.0, 0.0)], "neighbour behind")
    cpp_case((0.1, -0.2), (0.1, 0.1), (0.14, 0.14),
             [(0.5, 0.1, 2.0, 0.12, 1.0), (0.2, 0.3, -1.0, 0.1, -0.5)], "two neighbours, turning")
    cpp_case((1.5, 0.0), (0.2, 0.0), (0.2, 0.0), [], "wall within 1 s")
    cpp_case((1.55, 0.95), (0.0, 0.0), (0.2, 0.2), [(1.2, 0.95, 0.0, 0.1, 0.0)], "corner, neighbour behind")


def random_cases(seed=7, count=24):
    rng = np.random.default_rng(seed)
    print(f"      // Random (seed {seed}).")
    for _ in range(count):
        pos = rng.uniform([-1.55, -0.95], [1.55, 0.95])
        dxi = rng.uniform(-0.14, 0.14, 2)
        ang = rng.uniform(0, 2 * np.pi)
        desired = 0.2 * np.array([np.cos(ang), np.sin(ang)])
        nbrs = []
        for _ in range(rng.integers(0, 5)):
            rel = rng.uniform(-0.8, 0.8, 2)
            if np.hypot(rel[0], rel[1]) <= 0.25:
                # Within the safety radius the two legs coincide and numpy
                # breaks the resulting tie by the last bit of its sin/cos.
                continue
            nbrs.append((pos[0] + rel[0], pos[1] + rel[1], rng.uniform(-np.pi, np.pi),
                         rng.uniform(0, 0.2), rng.uniform(-3, 3)))
        cpp_case(pos, dxi, desired, nbrs)


if __name__ == "__main__":
    hand_made_cases()
    random_cases()
