#!/usr/bin/python3
"""lossy_relay: a user-space stand-in for tc netem between network namespaces (standard library only).

Runs in the middle namespace of lossy_three_namespaces.py, which joins three namespaces (world,
agents_a, agents_b) to it by veth pairs. Every LCM multicast datagram (group:port) that arrives on
one link is sent out of each other link, impaired per outgoing link as `tc qdisc ... netem loss 5%
delay 20ms reorder 25%` would: dropped with probability --loss, else held --delay seconds, except
that a fraction --reorder goes out at once and so overtakes the datagrams still held. The relay is
the only path between the namespaces (no IP forwarding, no multicast routing), so a run that works
across them went through it.

Counts go to --stats as JSON (replaced atomically every second and on SIGTERM): per link the
datagrams received and sent, dropped, sent early, and how many left after a later one (reordered).

Usage: lossy_relay.py --links m_world,m_a,m_b --stats FILE [--loss 0.05] [--delay 0.02] [--reorder 0.25] [--seed N]
"""

import argparse
import heapq
import json
import os
import random
import select
import signal
import socket
import struct
import sys
import time

SO_BINDTODEVICE = getattr(socket, "SO_BINDTODEVICE", 25)


def interface_address(name):
    """The IPv4 address of interface `name` (SIOCGIFADDR)."""
    import fcntl

    probe = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        request = struct.pack("256s", name.encode()[:15])
        return socket.inet_ntoa(fcntl.ioctl(probe.fileno(), 0x8915, request)[20:24])
    finally:
        probe.close()


class Link:
    """One veth end of the middle namespace: a socket that hears the group on it, one that sends on it."""

    def __init__(self, name, group, port):
        self.name = name
        index = socket.if_nametoindex(name)
        self.receiver = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
        self.receiver.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.receiver.setsockopt(socket.SOL_SOCKET, SO_BINDTODEVICE, name.encode())
        self.receiver.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
        self.receiver.bind((group, port))
        membership = struct.pack("4s4si", socket.inet_aton(group), socket.inet_aton("0.0.0.0"), index)
        self.receiver.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
        self.sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
        self.sender.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_IF, socket.inet_aton(interface_address(name)))
        self.sender.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 1)
        self.sender.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 0)
        self.counts = {"received": 0, "sent": 0, "dropped": 0, "sent_early": 0, "reordered": 0}
        self.last_sent_order = -1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--links", required=True, help="comma-separated interface names")
    parser.add_argument("--stats", required=True)
    parser.add_argument("--group", default="239.255.76.67")
    parser.add_argument("--port", type=int, default=7667)
    parser.add_argument("--loss", type=float, default=0.05)
    parser.add_argument("--delay", type=float, default=0.020)
    parser.add_argument("--reorder", type=float, default=0.25)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    links = [Link(name, args.group, args.port) for name in args.links.split(",")]
    by_socket = {link.receiver: link for link in links}
    chance = random.Random(args.seed)
    held = []  # heap of (due time, arrival order, outgoing link index, datagram)
    order = 0
    stopping = False

    def stop(*_):
        nonlocal stopping
        stopping = True

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)

    def write_stats():
        stats = {"loss": args.loss, "delay_s": args.delay, "reorder": args.reorder,
                 "links": {link.name: link.counts for link in links}}
        temporary = args.stats + ".tmp"
        with open(temporary, "w") as f:
            json.dump(stats, f)
        os.replace(temporary, args.stats)

    print(f"relaying {args.group}:{args.port} between {args.links}: loss {args.loss:.0%}, delay "
          f"{args.delay * 1000:.0f} ms, {args.reorder:.0%} sent early (reordered)", flush=True)
    next_stats = time.monotonic()
    while not stopping:
        now = time.monotonic()
        while held and held[0][0] <= now:
            _, arrival, index, datagram = heapq.heappop(held)
            link = links[index]
            link.sender.sendto(datagram, (args.group, args.port))
            link.counts["sent"] += 1
            if arrival < link.last_sent_order:
                link.counts["reordered"] += 1
            link.last_sent_order = max(link.last_sent_order, arrival)
        if now >= next_stats:
            write_stats()
            next_stats = now + 1.0
        timeout = max(0.0, min(held[0][0] - now if held else 0.1, next_stats - now))
        try:
            readable, _, _ = select.select(list(by_socket), [], [], timeout)
        except InterruptedError:
            continue
        for receiver in readable:
            source = by_socket[receiver]
            datagram = receiver.recv(65536)
            source.counts["received"] += 1
            arrival_time = time.monotonic()
            for index, link in enumerate(links):
                if link is source:
                    continue
                if chance.random() < args.loss:
                    link.counts["dropped"] += 1
                    continue
                early = chance.random() < args.reorder
                if early:
                    link.counts["sent_early"] += 1
                heapq.heappush(held, (arrival_time + (0.0 if early else args.delay), order, index, datagram))
                order += 1
    write_stats()
    return 0


if __name__ == "__main__":
    sys.exit(main())
