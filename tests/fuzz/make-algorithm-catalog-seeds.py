#!/usr/bin/env python3
"""Writes tests/fuzz/algorithm_catalog-corpus: a TraverseAlgorithm (after a 16-bit big-endian length)
and a GetParametersSelectionValuesResponse, as a UgCS server describes its tools (field numbers from
shared/hci-proto-catalog.md). Run from the repository's root."""
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


def field(number, value):
    if isinstance(value, int):
        return varint(number << 3) + varint(value)
    if isinstance(value, str):
        value = value.encode()
    return varint(number << 3 | 2) + varint(len(value)) + value


def parameter(name, kind, default=None, semantic=None, mandatory=True, advanced=False, regex=None, description=None):
    m = field(4, name) + field(6, kind) + field(7, 1 if mandatory else 0) + field(13, 0 if advanced else 1)
    if default is not None:
        m += field(8, default)
    if semantic is not None:
        m += field(11, semantic)
    if regex is not None:
        m += field(9, regex)
    if description is not None:
        m += field(5, description)
    return m


def algorithm(name, cls, figure, parameters, id=0):
    m = field(1, id) + field(4, name) + field(5, cls) + field(6, 1) + field(7, figure)
    for p in parameters:
        m += field(9, p)
    return m


def selection(selection_id, items):
    m = field(1, selection_id)
    for value, description, default in items:
        m += field(2, field(1, value) + field(2, description) + field(3, 1 if default else 0))
    return m


def seed(name, alg, selections=()):
    body = b''.join(field(1, s) for s in selections)
    open(f'tests/fuzz/algorithm_catalog-corpus/{name}.bin', 'wb').write(struct.pack('>H', len(alg)) + alg + body)


PT_STRING, PT_INTEGER, PT_DOUBLE, PT_BOOLEAN, PT_SELECTION = range(5)
PS_ALTITUDE, PS_SPEED, PS_GSD = 2, 3, 6
photogrammetry = 'com.ugcs.ucs.service.routing.impl.PhotogrammetryAlgorithm'
seed('photogrammetry-as-the-server-lists-it', algorithm('Photogrammetry', photogrammetry, 1, [
    parameter('speed', PT_DOUBLE, '5', PS_SPEED),
    parameter('camera', PT_SELECTION),
    parameter('groundSampleDistance', PT_DOUBLE, '2', PS_GSD),
    parameter('overlapForward', PT_DOUBLE, '60'),
    parameter('overlapSide', PT_DOUBLE, '30'),
    parameter('altitudeType', PT_SELECTION, 'AGL', advanced=True),
], id=12), [selection('camera', [('Sony A6000', 'Sony A6000 16 mm', True), ('Zenmuse X5', '', False)]),
            selection('altitudeType', [('AGL', 'Above ground', True), ('AMSL', 'Above sea level', False)])])
seed('a-newer-servers-own-tool', algorithm('Spiral', 'com.example.routing.SpiralAlgorithm', 2, [
    parameter('turns', PT_INTEGER, '7'),
    parameter('climb', PT_BOOLEAN, 'true', mandatory=False),
    parameter('label', PT_STRING, 'x', regex='[a-z]+', description='What to call it'),
    parameter('height', PT_DOUBLE, '40', PS_ALTITUDE),
]))
seed('defaults-that-are-not-their-type', algorithm('Circle', 'com.ugcs.ucs.service.routing.impl.CircleAlgorithm', 2, [
    parameter('speed', PT_DOUBLE, 'fast', PS_SPEED),
    parameter('loops', PT_INTEGER, '2.5'),
    parameter('clockwise', PT_BOOLEAN, 'maybe'),
    parameter('turnType', PT_SELECTION, 'SPLINE'),
]), [selection('turnType', [('STOP_AND_TURN', 'Stop and turn', False)]), selection('nothere', [('a', 'b', True)])])
seed('no-class-no-name', algorithm('', '', 6, [parameter('', PT_STRING)]))
