#!/usr/bin/env python3
"""Converts Natural Earth land outlines (TopoJSON from the npm package world-atlas) into
resources/land-50m.bin, the compact file Sortie's offline base map reads.

    cd "$(mktemp -d)" && npm pack world-atlas && tar xzf world-atlas-*.tgz
    python3 scripts/make-landmask.py package/land-50m.json resources/land-50m.bin

Output, zlib-compressed in Qt's qCompress framing (4-byte big-endian length, then the zlib stream):
    magic  b"SLAND001"
    uint32 polygon count
    per polygon: uint32 ring count; per ring: uint32 point count, then point count pairs of int32
                 (longitude, latitude) in 1e-5 degrees, the first absolute, the rest deltas
All integers little-endian. The first ring of a polygon is its outline, the others its holes.
Longitudes are unwrapped so that no ring jumps across the antimeridian (a ring may reach past
+-180, but its middle lies within it, and its holes lie inside it); a ring around a pole (Antarctica) is closed along the map's edge at +-89.999 degrees,
and the spherical hole that marks the pole itself is dropped.
"""
import json
import struct
import sys
import zlib


def decode_arcs(topology):
    sx, sy = topology["transform"]["scale"]
    tx, ty = topology["transform"]["translate"]
    arcs = []
    for arc in topology["arcs"]:
        x = y = 0
        points = []
        for dx, dy in arc:
            x += dx
            y += dy
            points.append((x * sx + tx, y * sy + ty))
        arcs.append(points)
    return arcs


def ring_points(ring, arcs):
    points = []
    for index in ring:
        arc = arcs[index] if index >= 0 else list(reversed(arcs[~index]))
        points.extend(arc if not points else arc[1:])
    return points


def unwrap(points):
    """Makes longitudes continuous; returns the points and the net longitude travelled."""
    out = [points[0]]
    offset = 0.0
    for (lon0, _), (lon1, lat1) in zip(points, points[1:]):
        if lon1 - lon0 > 180:
            offset -= 360
        elif lon1 - lon0 < -180:
            offset += 360
        out.append((lon1 + offset, lat1))
    return out, offset


def close_around_pole(points, travelled):
    """A ring whose longitudes travel a full turn encloses a pole: close it along that pole."""
    if travelled == 0:
        return points
    first_lon, _ = points[0]
    last_lon, _ = points[-1]
    pole = -89.999 if min(lat for _, lat in points) < 0 else 89.999
    return points + [(last_lon, pole), (first_lon, pole)]


def main():
    source, target = sys.argv[1], sys.argv[2]
    topology = json.load(open(source))
    arcs = decode_arcs(topology)
    polygons = []
    for geometry in topology["objects"]["land"]["geometries"]:
        shapes = geometry["arcs"] if geometry["type"] == "MultiPolygon" else [geometry["arcs"]]
        for shape in shapes:
            rings = []
            for index, ring in enumerate(shape):
                points, travelled = unwrap(ring_points(ring, arcs))
                if index > 0 and travelled != 0:
                    continue  # a hole around the pole: on a flat map it is the map's bottom edge
                points = close_around_pole(points, travelled)
                # The outline's middle goes within -180..180; each hole goes into its outline.
                lons = [lon for lon, _ in points]
                centre = (min(lons) + max(lons)) / 2
                anchor = 0.0 if index == 0 else outline_centre
                turns = round((centre - anchor) / 360) if index > 0 else (centre + 180) // 360
                points = [(lon - 360 * turns, lat) for lon, lat in points]
                if index == 0:
                    outline_centre = centre - 360 * turns
                rings.append(points)
            polygons.append(rings)

    body = bytearray(b"SLAND001")
    body += struct.pack("<I", len(polygons))
    total = 0
    for rings in polygons:
        body += struct.pack("<I", len(rings))
        for points in rings:
            body += struct.pack("<I", len(points))
            px = py = 0
            for lon, lat in points:
                x, y = round(lon * 1e5), round(lat * 1e5)
                body += struct.pack("<ii", x - px, y - py)
                px, py = x, y
            total += len(points)
    packed = struct.pack(">I", len(body)) + zlib.compress(bytes(body), 9)
    open(target, "wb").write(packed)
    print(f"{target}: {len(polygons)} polygons, {total} points, {len(packed)} bytes")


if __name__ == "__main__":
    main()
