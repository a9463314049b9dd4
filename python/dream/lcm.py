"""LCM from Python through the real LCM C library (Debian's liblcm.so.1), by ctypes.

Debian ships no Python binding for LCM and the project's machines reach no PyPI, so the
Python agents call liblcm's C API directly: lcm_create, lcm_subscribe, lcm_publish,
lcm_handle_timeout. Messages are the bytes lcm-gen's Python types encode and decode.

An `Lcm` either opens its own instance (a Python agent process) or wraps one that a C++
process opened (`Lcm.wrap`): `dream run` hosts Python agents on its own memq:// bus, so
the world and the Python agents share one in-process queue.
"""

import ctypes
import ctypes.util
import logging

_log = logging.getLogger("dream")

# LCM's default of 30 queued messages drops commands when many robots answer one step;
# the C++ LcmBus raises it to the same figure (lcmtypes/lcm/src/lcm_bus.cc, kQueueCapacity).
QUEUE_CAPACITY = 10000


class _RecvBuf(ctypes.Structure):
    _fields_ = [("data", ctypes.c_void_p), ("data_size", ctypes.c_uint32),
                ("recv_utime", ctypes.c_int64), ("lcm", ctypes.c_void_p)]


_HANDLER = ctypes.CFUNCTYPE(None, ctypes.POINTER(_RecvBuf), ctypes.c_char_p, ctypes.c_void_p)
_library = None


def _liblcm():
    """liblcm, loaded once; its functions typed so ctypes converts arguments correctly."""
    global _library
    if _library is not None:
        return _library
    name = ctypes.util.find_library("lcm") or "liblcm.so.1"
    try:
        lib = ctypes.CDLL(name)
    except OSError as error:
        raise RuntimeError(f"cannot load the LCM library ({name}): {error}; "
                           "install Debian's liblcm1 (apt-get install liblcm-dev)") from error
    lib.lcm_create.restype = ctypes.c_void_p
    lib.lcm_create.argtypes = [ctypes.c_char_p]
    lib.lcm_destroy.argtypes = [ctypes.c_void_p]
    lib.lcm_subscribe.restype = ctypes.c_void_p
    lib.lcm_subscribe.argtypes = [ctypes.c_void_p, ctypes.c_char_p, _HANDLER, ctypes.c_void_p]
    lib.lcm_unsubscribe.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
    lib.lcm_subscription_set_queue_capacity.argtypes = [ctypes.c_void_p, ctypes.c_int]
    lib.lcm_publish.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_void_p, ctypes.c_uint]
    lib.lcm_handle_timeout.argtypes = [ctypes.c_void_p, ctypes.c_int]
    _library = lib
    return lib


class Lcm:
    """One LCM instance: publish bytes, subscribe a handler(channel, data) to a regex."""

    def __init__(self, url, _address=None):
        self._lib = _liblcm()
        self.url = url
        self._owned = _address is None
        self._lcm = _address if _address is not None else self._lib.lcm_create(url.encode())
        if not self._lcm:
            raise RuntimeError(f"cannot open LCM on {url!r}: check the URL, and for udpm:// that "
                               "the machine has a multicast route (see docs/architecture.md)")
        self._subscriptions = []  # (subscription, callback): the callback must outlive it

    @classmethod
    def wrap(cls, address, url):
        """An Lcm over an lcm_t* another part of this process opened (and will close)."""
        return cls(url, _address=ctypes.c_void_p(address).value)

    def subscribe(self, channel_regex, handler):
        """handler(channel: str, data: bytes) for every message on a matching channel."""

        def deliver(buffer, channel, _user):
            # Nothing may escape into LCM's C code: ctypes would print "Exception ignored" and
            # drop it. The handler keeps its own errors (AgentHost._on_message); what is left
            # (a RecursionError while it handled one) is logged here.
            try:
                record = buffer.contents
                handler(channel.decode("utf-8", "replace"), ctypes.string_at(record.data, record.data_size))
            except BaseException as error:  # noqa: B036 - see above
                _log.error("%s: a message handler failed: %s: %s", channel.decode("utf-8", "replace"),
                           type(error).__name__, error)

        callback = _HANDLER(deliver)
        subscription = self._lib.lcm_subscribe(self._lcm, channel_regex.encode(), callback, None)
        if not subscription:
            raise RuntimeError(f"cannot subscribe to {channel_regex!r} on {self.url}")
        self._lib.lcm_subscription_set_queue_capacity(subscription, QUEUE_CAPACITY)
        self._subscriptions.append((subscription, callback))

    def publish(self, channel, data):
        if self._lib.lcm_publish(self._lcm, channel.encode(), data, len(data)) != 0:
            raise RuntimeError(f"LCM refused to publish on {channel} ({self.url})")

    def handle_timeout(self, timeout_ms):
        """Dispatches at most one message; 0 on timeout, < 0 on error."""
        return self._lib.lcm_handle_timeout(self._lcm, int(timeout_ms))

    def close(self):
        """Drops this object's subscriptions; closes the instance if this object opened it."""
        if self._lcm is None:
            return
        for subscription, _callback in self._subscriptions:
            self._lib.lcm_unsubscribe(self._lcm, subscription)
        self._subscriptions.clear()
        if self._owned:
            self._lib.lcm_destroy(self._lcm)
        self._lcm = None
