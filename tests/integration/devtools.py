"""A small client of Chromium's DevTools protocol, standard library only, for tests that drive
headless Chromium (`chromium --headless=new --remote-debugging-port=0`): the WebSocket the
protocol runs on (RFC 6455, text frames, client side), Runtime.evaluate and Page.captureScreenshot.
"""

import base64
import json
import os
import socket
import struct
import time
import urllib.parse
import urllib.request

from dreamtest import check, fail


class WebSocket:
    """A client WebSocket over TCP: text messages out (masked, as a client must), messages in."""

    def __init__(self, url, timeout=10):
        parsed = urllib.parse.urlparse(url)
        check(parsed.scheme == "ws", f"devtools: not a ws:// URL: {url}")
        self.sock = socket.create_connection((parsed.hostname, parsed.port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        request = (f"GET {parsed.path} HTTP/1.1\r\nHost: {parsed.hostname}:{parsed.port}\r\nUpgrade: websocket\r\n"
                   f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        self.sock.sendall(request.encode())
        self.buffer = b""
        while b"\r\n\r\n" not in self.buffer:
            chunk = self.sock.recv(4096)
            check(chunk, f"devtools: {url} closed during the handshake")
            self.buffer += chunk
        head, self.buffer = self.buffer.split(b"\r\n\r\n", 1)
        check(head.startswith(b"HTTP/1.1 101"), f"devtools: handshake refused: {head[:80]!r}")

    def _read(self, n):
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 16)
            check(chunk, "devtools: connection closed")
            self.buffer += chunk
        data, self.buffer = self.buffer[:n], self.buffer[n:]
        return data

    def send(self, text):
        payload = text.encode()
        header = bytes([0x81])
        if len(payload) < 126:
            header += bytes([0x80 | len(payload)])
        elif len(payload) < 1 << 16:
            header += bytes([0x80 | 126]) + struct.pack(">H", len(payload))
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", len(payload))
        mask = os.urandom(4)
        self.sock.sendall(header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def receive(self):
        """The next whole text message (fragments joined; pings and other frames skipped)."""
        message = b""
        while True:
            first, second = self._read(2)
            length = second & 0x7F
            if length == 126:
                length = struct.unpack(">H", self._read(2))[0]
            elif length == 127:
                length = struct.unpack(">Q", self._read(8))[0]
            data = self._read(length)
            opcode = first & 0x0F
            if opcode == 0x8:
                fail("devtools: the browser closed the connection")
            if opcode in (0x0, 0x1, 0x2):
                message += data
                if first & 0x80:
                    return message.decode()

    def close(self):
        self.sock.close()


class Page:
    """One page of a headless Chromium, driven over its DevTools WebSocket."""

    def __init__(self, devtools_port, timeout=10):
        deadline = time.monotonic() + timeout
        while True:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{devtools_port}/json/list", timeout=2) as response:
                    targets = json.load(response)
                pages = [t for t in targets if t.get("type") == "page"]
                if pages:
                    break
            except OSError:
                pass
            check(time.monotonic() < deadline, f"devtools: no page on port {devtools_port} within {timeout} s")
            time.sleep(0.1)
        self.ws = WebSocket(pages[0]["webSocketDebuggerUrl"])
        self.next_id = 0

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            reply = json.loads(self.ws.receive())
            if reply.get("id") == self.next_id:
                check("error" not in reply, f"devtools: {method} failed: {reply.get('error')}")
                return reply["result"]

    def evaluate(self, expression):
        """The value of a JavaScript expression in the page (JSON-able values)."""
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        check("exceptionDetails" not in result, f"devtools: `{expression}` threw: {result.get('exceptionDetails')}")
        return result["result"].get("value")

    def navigate(self, url):
        self.call("Page.navigate", url=url)

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))
        return path

    def close(self):
        self.ws.close()


def devtools_port(user_data_dir, timeout=60):
    """The port a Chromium started with --remote-debugging-port=0 chose (its DevToolsActivePort file).
    Chromium took over 15 s to start on two cores busy with other tests: a wait, not a speed check."""
    path = os.path.join(user_data_dir, "DevToolsActivePort")
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            with open(path) as f:
                first = f.readline().strip()
            if first.isdigit():
                return int(first)
        except OSError:
            pass
        time.sleep(0.05)
    fail(f"chromium wrote no {path} within {timeout} s")


def chromium_argv(user_data_dir, url):
    """Headless Chromium, as root in a container (--no-sandbox), no GPU, nothing fetched from outside."""
    return ["chromium", "--headless=new", "--no-sandbox", "--disable-gpu", "--remote-debugging-port=0",
            f"--user-data-dir={user_data_dir}", "--window-size=1280,800", "--no-first-run",
            "--no-default-browser-check", "--disable-extensions", "--disable-background-networking",
            "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage", url]


def view_state(page):
    """The view page's state (window.dreamView.state), or None before the page has one."""
    return page.evaluate("window.dreamView ? window.dreamView.state : null")


def wait_for_view(page, what, predicate, timeout):
    """The page's state once `predicate` holds; `timeout` only turns a page that never gets there
    into a failure (generous: Chromium on a loaded machine can take seconds per frame)."""
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        last = view_state(page)
        if last and predicate(last):
            return last
        time.sleep(0.03)
    fail(f"the page did not show {what} within {timeout} s; its state: {json.dumps(last)[:800]}")
