#!/usr/bin/env python3
"""A TCP proxy for tests that puts network faults between players and carrom-server.

    fault_proxy.py --target HOST:PORT --control FILE [--listen HOST:PORT]
                   [--delay-ms D --jitter-ms J --seed S]

Prints "listening on HOST:PORT" on stdout once it accepts connections, then forwards every
connection to the target, bytes in order. Every 50 ms it looks for the control file; when it
exists, it reads one command from it, deletes it, and obeys:

    cut D    resets every open connection (both sides) and refuses new ones for D seconds
             (the listening socket is closed: connects are refused), then listens again.
    stall D  stops forwarding in both directions and refuses new connections for D seconds,
             then delivers what waited (in order, including a side's end), as TCP does after
             an outage where no packet passes.

Each command is confirmed on stdout ("cut 2 connections for 3.0 s", "open").

With --delay-ms, every chunk read from either side is delivered D ms later plus a jitter drawn
uniformly from [-J, J] ms, but never before the chunk read ahead of it on the same side: bytes
keep their order, as TCP delivers them over a path whose delay varies. A round trip through
the proxy gains 2 D on average.
"""
import argparse
import asyncio
import os
import random
import socket
import struct
import sys


class Proxy:
    def __init__(self, listen_host, listen_port, target_host, target_port,
                 delay_s=0.0, jitter_s=0.0, seed=1):
        self.delay_s = delay_s
        self.jitter_s = jitter_s
        self.random = random.Random(seed)
        self.listen_host = listen_host
        self.listen_port = listen_port
        self.target = (target_host, target_port)
        self.server = None
        self.pairs = set()  # (client writer, server writer)
        self.flowing = asyncio.Event()
        self.flowing.set()

    async def listen(self):
        self.server = await asyncio.start_server(
            self.accept, self.listen_host, self.listen_port, reuse_address=True)
        self.listen_port = self.server.sockets[0].getsockname()[1]

    async def stop_listening(self):
        self.server.close()
        await self.server.wait_closed()

    async def accept(self, client_reader, client_writer):
        try:
            server_reader, server_writer = await asyncio.open_connection(*self.target)
        except OSError:
            client_writer.close()
            return
        pair = (client_writer, server_writer)
        self.pairs.add(pair)
        try:
            await asyncio.gather(self.pump(client_reader, server_writer),
                                 self.pump(server_reader, client_writer))
        finally:
            self.pairs.discard(pair)
            for w in pair:
                w.close()

    async def pump(self, reader, writer):
        if self.delay_s <= 0.0 and self.jitter_s <= 0.0:
            await self.pump_now(reader, writer)
            return
        queue = asyncio.Queue()
        deliver = asyncio.ensure_future(self.deliver(queue, writer))
        loop = asyncio.get_running_loop()
        last_due = 0.0
        try:
            while True:
                data = await reader.read(65536)
                delay = self.delay_s + self.random.uniform(-self.jitter_s, self.jitter_s)
                last_due = max(last_due, loop.time() + max(delay, 0.0))
                queue.put_nowait((last_due, data))
                if not data:
                    break
        except Exception:
            queue.put_nowait((0.0, None))
        await deliver

    async def deliver(self, queue, writer):
        """Writes each queued chunk at its due time, in order; b"" is the end, None a reset."""
        loop = asyncio.get_running_loop()
        try:
            while True:
                due, data = await queue.get()
                if data is None:
                    reset(writer)
                    return
                wait = due - loop.time()
                if wait > 0:
                    await asyncio.sleep(wait)
                await self.flowing.wait()
                if not data:
                    if writer.can_write_eof():
                        writer.write_eof()
                    return
                writer.write(data)
                await writer.drain()
        except Exception:
            reset(writer)

    async def pump_now(self, reader, writer):
        try:
            while True:
                await self.flowing.wait()
                data = await reader.read(65536)
                await self.flowing.wait()  # what was read during a stall waits for its end
                if not data:
                    if writer.can_write_eof():
                        writer.write_eof()
                    return
                writer.write(data)
                await writer.drain()
        except Exception:  # the other side ended or was cut: end this one too
            reset(writer)

    async def cut(self, seconds):
        await self.stop_listening()
        count = len(self.pairs)
        for pair in list(self.pairs):
            for w in pair:
                reset(w)
        print(f"cut {count} connections for {seconds:.1f} s", flush=True)
        await asyncio.sleep(seconds)
        await self.listen()
        print("open", flush=True)

    async def stall(self, seconds):
        await self.stop_listening()
        self.flowing.clear()
        print(f"stalled {len(self.pairs)} connections for {seconds:.1f} s", flush=True)
        await asyncio.sleep(seconds)
        self.flowing.set()
        await self.listen()
        print("open", flush=True)


def reset(writer):
    """Closes with a TCP reset (SO_LINGER 0), as a broken path ends for the side that writes."""
    sock = writer.get_extra_info("socket")
    if sock is not None:
        try:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        except OSError:
            pass
    if not writer.transport.is_closing():
        writer.transport.abort()


def host_port(text):
    host, _, port = text.rpartition(":")
    return host, int(port)


async def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--target", required=True, help="HOST:PORT of the server")
    parser.add_argument("--control", required=True, help="the command file to watch")
    parser.add_argument("--listen", default="127.0.0.1:0", help="HOST:PORT (0 = ephemeral)")
    parser.add_argument("--delay-ms", type=float, default=0.0, help="added one-way delay, ms")
    parser.add_argument("--jitter-ms", type=float, default=0.0, help="+- this, uniform, ms")
    parser.add_argument("--seed", type=int, default=1, help="seed of the jitter")
    args = parser.parse_args()
    proxy = Proxy(*host_port(args.listen), *host_port(args.target),
                  args.delay_ms / 1000.0, args.jitter_ms / 1000.0, args.seed)
    await proxy.listen()
    print(f"listening on {proxy.listen_host}:{proxy.listen_port}", flush=True)
    while True:
        await asyncio.sleep(0.05)
        if not os.path.exists(args.control):
            continue
        with open(args.control) as f:
            words = f.read().split()
        os.remove(args.control)
        if len(words) != 2 or words[0] not in ("cut", "stall"):
            print(f"unknown command {' '.join(words)!r}", flush=True)
            continue
        seconds = float(words[1])
        await (proxy.cut(seconds) if words[0] == "cut" else proxy.stall(seconds))


if __name__ == "__main__":
    try:
        asyncio.run(main())
    except KeyboardInterrupt:
        sys.exit(0)
