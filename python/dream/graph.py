"""The Robotarium V2 graph helpers (rps.utilities.graph), written for DREAM from their
definitions: graph Laplacians and neighbour queries, with the same arguments, results and, for the
random graphs, the same draws from numpy's global stream in the same order, so a seeded script
gets the same graph (tests/python/test_toolbox.py holds them to the official ones)."""

import numpy as np

from .toolbox_checks import ToolboxArgumentError, non_negative, rows, whole


def _add_edge(laplacian, i, j):
    laplacian[i, j] = -1
    laplacian[j, i] = -1
    laplacian[i, i] += 1
    laplacian[j, j] += 1


def completeGL(n):
    """Every node joined to every other: n I - 1 1^T."""
    n = whole("completeGL", "n", n, 1)
    return n * np.eye(n) - np.ones((n, n))


def _path(n):
    return 2 * np.eye(n) - np.diag(np.ones(n - 1), 1) - np.diag(np.ones(n - 1), -1)


def cycleGL(n):
    """A ring: every node joined to the one before and the one after it."""
    n = whole("cycleGL", "n", n, 3)
    laplacian = _path(n)
    laplacian[0, n - 1] = -1
    laplacian[n - 1, 0] = -1
    return laplacian


def lineGL(n):
    """A path: node i joined to i + 1."""
    n = whole("lineGL", "n", n, 2)
    laplacian = _path(n)
    laplacian[0, 0] = 1
    laplacian[n - 1, n - 1] = 1
    return laplacian


def _add_random_edges(laplacian, candidates, e):
    count = min(e, len(candidates))
    if count > 0:
        np.random.shuffle(candidates)
        for i, j in candidates[:count]:
            _add_edge(laplacian, i, j)
    return laplacian


def random_connectedGL(v, e):
    """A random spanning tree (node i joined to a uniformly drawn earlier node), then up to e more
    edges drawn uniformly from the pairs not yet joined."""
    v = whole("random_connectedGL", "v", v, 1)
    e = whole("random_connectedGL", "e", e, 0)
    laplacian = np.zeros((v, v))
    for i in range(1, v):
        _add_edge(laplacian, i, np.random.randint(0, i))
    return _add_random_edges(laplacian, np.argwhere(np.triu(laplacian == 0, 1)), e)


def randomGL(v, e):
    """Up to e edges drawn uniformly from all pairs; the graph may be disconnected."""
    v = whole("randomGL", "v", v, 1)
    e = whole("randomGL", "e", e, 0)
    laplacian = np.zeros((v, v))
    return _add_random_edges(laplacian, np.argwhere(np.triu(np.ones((v, v)), 1)), e)


def _agent(function, agent, count):
    if isinstance(agent, bool) or not isinstance(agent, (int, np.integer)) or not 0 <= agent < count:
        raise ToolboxArgumentError("%s: agent must be a robot index from 0 to %d, got %r" %
                                   (function, count - 1, agent))
    return int(agent)


def delta_disk_neighbors(poses, agent, delta):
    """The indices of the other robots within delta metres of robot `agent` (poses: 2 or 3 x N)."""
    poses = rows("delta_disk_neighbors", "poses", poses, 2, at_least=True)
    agent = _agent("delta_disk_neighbors", agent, poses.shape[1])
    delta = non_negative("delta_disk_neighbors", "delta", delta)
    others = np.delete(np.arange(poses.shape[1]), agent)
    distances = np.linalg.norm(poses[:2, others] - poses[:2, agent:agent + 1], axis=0)
    return others[distances <= delta]


def topological_neighbors(L, agent):
    """The indices of robot `agent`'s neighbours in the graph of Laplacian L."""
    laplacian = np.asarray(L, dtype=float)
    if laplacian.ndim != 2 or laplacian.shape[0] != laplacian.shape[1]:
        raise ToolboxArgumentError("topological_neighbors: L must be a square N x N Laplacian, got shape %s" %
                                   (laplacian.shape,))
    agent = _agent("topological_neighbors", agent, laplacian.shape[0])
    row = laplacian[agent, :].copy()
    row[agent] = 0
    return np.where(row != 0)[0]
