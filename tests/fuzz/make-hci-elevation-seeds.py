#!/usr/bin/env python3
"""Writes tests/fuzz/hci_elevation-corpus: GetElevationProfileResponse messages (field numbers from
shared/hci-proto-catalog.md) along fuzz_hci_elevation's path near Riga. Run from the repository's root."""
import math
import struct


def varint(v):
    out = b''
    while True:
        c = v & 0x7f
        v >>= 7
        if v:
            out += bytes([c | 0x80])
        else:
            return out + bytes([c])


def double(number, value):
    return varint(number << 3 | 1) + struct.pack('<d', value)


def message(number, body):
    return varint(number << 3 | 2) + varint(len(body)) + body


def location(lat, lon):  # Wgs84LocationDto: every field is required
    return message(1, double(1, math.radians(lat)) + double(2, math.radians(lon)) + double(3, 0.0) + varint(4 << 3) + varint(0))


def profile(points, elevations):
    return b''.join(location(*p) for p in points) + b''.join(double(2, e) for e in elevations)


def along(a, b, n):
    return [(a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n) for i in range(n + 1)]


legs = along((56.95, 24.10), (56.955, 24.11), 10) + along((56.955, 24.11), (56.96, 24.10), 10)[1:]
heights = [12 + 3 * math.sin(i / 3) for i in range(len(legs))]
seeds = {
    'a-server-sampling-its-own-way': profile(legs, heights),
    'values-that-are-not-numbers': profile(legs[:6], [10.0, float('nan'), float('inf'), -float('inf'), 1e308, 14.0]),
    'fewer-values-than-places': profile(legs, heights[:4]),
    'places-off-the-earth': profile([(123.0, 24.1), (56.95, 400.0)] + legs[2:], heights),
    'one-place': profile(legs[:1], [9.5]),
}
for name, body in seeds.items():
    open(f'tests/fuzz/hci_elevation-corpus/{name}.bin', 'wb').write(body)
