"""Argument checks shared by the Robotarium toolbox modules (transformations, controllers, graph,
misc). A bad argument raises ToolboxArgumentError, which is both a ValueError (what Python code
expects) and an AssertionError (what the official rps raises, so a script that catches it keeps
working), and names the function, the argument and the value."""

import math

import numpy as np


class ToolboxArgumentError(ValueError, AssertionError):
    pass


def positive(function, name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise ToolboxArgumentError("%s: %s must be a positive number, got %r" % (function, name, value))
    return value


def non_negative(function, name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
        raise ToolboxArgumentError("%s: %s must be a non-negative number, got %r" % (function, name, value))
    return value


def whole(function, name, value, least):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least:
        raise ToolboxArgumentError("%s: %s must be a whole number of at least %d, got %r" %
                                   (function, name, least, value))
    return int(value)


def rows(function, name, array, count, at_least=False):
    """array as a float 2-D array of `count` rows (at least `count` if at_least) and any columns."""
    a = np.asarray(array, dtype=float)
    if a.ndim != 2 or (a.shape[0] < count if at_least else a.shape[0] != count):
        raise ToolboxArgumentError("%s: %s must be %s%d x N, got shape %s" %
                                   (function, name, "at least " if at_least else "", count, a.shape))
    return a


def same_columns(function, first_name, first, second_name, second):
    if first.shape[1] != second.shape[1]:
        raise ToolboxArgumentError("%s: %s and %s must have the same number of columns (%d vs %d)" %
                                   (function, first_name, second_name, first.shape[1], second.shape[1]))


def pair(function, first_name, first, first_rows, second_name, second, second_rows, first_at_least=False):
    """Two arrays, first_rows x N (at least, if first_at_least) and second_rows x N, checked."""
    first = rows(function, first_name, first, first_rows, at_least=first_at_least)
    second = rows(function, second_name, second, second_rows)
    same_columns(function, first_name, first, second_name, second)
    return first, second


def wrap(angle):
    """An angle (or array of them) wrapped to [-pi, pi], as rps wraps: atan2(sin, cos)."""
    return np.arctan2(np.sin(angle), np.cos(angle))
