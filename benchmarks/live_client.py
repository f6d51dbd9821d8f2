"""A Foxglove WebSocket client for the daemon benchmark, in a process of its own as the
Foxglove app would be: subscribes to every channel the live server advertises and reads (or,
with --stall, stops reading after subscribing). Prints how many messages it received.

    python benchmarks/live_client.py PORT SECONDS [--stall]
"""

from __future__ import annotations

import json
import sys
import time

from websockets.exceptions import ConnectionClosed
from websockets.sync.client import connect


def main() -> None:
    port, seconds = int(sys.argv[1]), float(sys.argv[2])
    stall = "--stall" in sys.argv
    deadline = time.monotonic() + seconds
    for _ in range(200):  # the server starts with the recorder
        try:
            ws = connect(f"ws://127.0.0.1:{port}", subprotocols=["foxglove.sdk.v1"])
            break
        except OSError:
            time.sleep(0.05)
    else:
        sys.exit("live_client: no server")
    got = 0
    with ws:
        channels: list[int] = []
        while not channels:
            msg = json.loads(ws.recv(timeout=30))
            if msg["op"] == "advertise":
                channels = [c["id"] for c in msg["channels"]]
        ws.send(json.dumps({"op": "subscribe", "subscriptions": [
            {"id": k, "channelId": c} for k, c in enumerate(channels)]}))
        print("subscribed", flush=True)
        if stall:
            time.sleep(max(0.0, deadline - time.monotonic()))
        else:
            while time.monotonic() < deadline:
                try:
                    if isinstance(ws.recv(timeout=0.2), bytes):
                        got += 1
                except TimeoutError:
                    continue
                except ConnectionClosed:
                    break
    print(got, flush=True)


if __name__ == "__main__":
    main()
