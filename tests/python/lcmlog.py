"""Read LCM event logs (such as a run's run.lcmlog) with nothing but the standard library.

Debian ships no LCM Python runtime; the types lcm-gen writes for Python only need
`struct` and `io`, and so does this reader. Together they decode a run:

    import sys; sys.path.insert(0, "build/python")
    import dream
    from lcmlog import read_events

    for event in read_events("runs/go_to_goal/run.lcmlog"):
        if event.channel == "DREAM_POSES":
            poses = dream.robot_poses_t.decode(event.data)

The file format (LCM's, every number big-endian): a sequence of events, each
    uint32 sync word 0xEDA1DA01, int64 event number, int64 timestamp (us),
    int32 channel length, int32 data length, channel bytes, data bytes.
"""

import struct
from typing import Iterator, NamedTuple

SYNC_WORD = 0xEDA1DA01
_HEADER = struct.Struct(">Iqqii")  # sync word, event number, timestamp, channel length, data length


class LogEvent(NamedTuple):
    """One event of an LCM log."""

    eventnum: int  # event number as written by the logger
    utime: int  # timestamp, microseconds (simulated time in dream run logs)
    channel: str  # channel name, e.g. DREAM_POSES
    data: bytes  # the encoded message: 8-byte type fingerprint, then the fields


class LogFormatError(ValueError):
    """The file is not an LCM log, or it is cut short or damaged."""


def read_events(path: str) -> Iterator[LogEvent]:
    """Yields every event of the LCM log at `path`, in file order.

    Raises LogFormatError, naming the file, the event and the byte offset, when
    the file does not start with an event, is cut short in the middle of an
    event, or an event header is damaged. An empty file is an empty log.
    """
    with open(path, "rb") as log:
        offset = 0
        count = 0
        while True:
            header = log.read(_HEADER.size)
            if not header:
                return
            where = f"{path}: event {count} at byte {offset}"
            if len(header) < _HEADER.size:
                raise LogFormatError(f"{where}: cut short inside the event header "
                                     f"({len(header)} of {_HEADER.size} bytes)")
            sync, eventnum, utime, channel_len, data_len = _HEADER.unpack(header)
            if sync != SYNC_WORD:
                what = "not an LCM log" if count == 0 else "damaged"
                raise LogFormatError(f"{where}: {what}: sync word is {sync:#010x}, expected {SYNC_WORD:#010x}")
            if channel_len <= 0 or data_len < 0:
                raise LogFormatError(f"{where}: damaged header: channel length {channel_len}, "
                                     f"data length {data_len}")
            body = log.read(channel_len + data_len)
            if len(body) < channel_len + data_len:
                raise LogFormatError(f"{where}: cut short: the header announces {channel_len + data_len} "
                                     f"bytes of channel and data, the file holds {len(body)}")
            try:
                channel = body[:channel_len].decode("utf-8")
            except UnicodeDecodeError as error:
                raise LogFormatError(f"{where}: damaged channel name: {error}") from None
            yield LogEvent(eventnum, utime, channel, body[channel_len:])
            offset += _HEADER.size + channel_len + data_len
            count += 1


def read_all(path: str) -> list:
    """All events of the log at `path` (see read_events)."""
    return list(read_events(path))
