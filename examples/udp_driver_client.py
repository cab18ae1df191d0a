#!/usr/bin/env python3
"""Drive the ego of examples/udp_driver.xosc over UDP, as a client of esmini's UDPDriverController.

Start the server first, then this client:

    osc2cr serve examples/udp_driver.xosc --udp -o out/
    python3 examples/udp_driver_client.py

It sends one driverInput message per simulation step to 127.0.0.1:49950 (esmini's base port
49950 plus the ego's object id 0). The scenario's controller is synchronous, so the server reads
one datagram per step and waits for it: the client sets the pace, and the same messages always
give the same run. The ego speeds up for 2 s, holds its speed, and brakes from 6 s on; the car
ahead brakes once the ego comes within 25 m of it.

A message (esmini's ControllerUDPDriver.hpp, version 1, little-endian): four unsigned 32-bit
integers -- version 1, inputMode (1: driverInput), objectId, frameNumber -- then throttle,
brake (0..1) and steering angle (rad) as doubles. Standard library only.
"""

import argparse
import socket
import struct
import time

VERSION = 1
DRIVER_INPUT = 1


def driver_input(object_id, frame, throttle, brake, steering):
    return struct.pack("<IIIIddd", VERSION, DRIVER_INPUT, object_id, frame, throttle, brake, steering)


def pedals(t):
    """Throttle and brake at simulated time t: esmini's vehicle model gives 20 m/s² per unit."""
    if t < 2.0:
        return 0.1, 0.0   # +2 m/s²
    if t < 6.0:
        return 1e-4, 0.0  # hold the speed (a pedal at 0 would let the model's drag slow it)
    return 0.0, 0.3       # -6 m/s² until it stands


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, default=49950)
    parser.add_argument("--object-id", type=int, default=0)
    parser.add_argument("--step", type=float, default=0.01, help="the server's engine step, s")
    parser.add_argument("--seconds", type=float, default=12.05, help="simulated time to drive, s")
    parser.add_argument("--interval", type=float, default=0.002, help="wall-clock pause between messages, s")
    args = parser.parse_args()

    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    frames = int(round(args.seconds / args.step)) + 1
    for frame in range(frames):  # frame 0 is read with the scenario's Init, frame k by step k
        throttle, brake = pedals(frame * args.step)
        sock.sendto(driver_input(args.object_id, frame, throttle, brake, 0.0), (args.host, args.port))
        time.sleep(args.interval)
    print(f"sent {frames} driverInput messages to {args.host}:{args.port}")


if __name__ == "__main__":
    main()
