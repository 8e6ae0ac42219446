#pragma once

#include <QtGlobal>

namespace sortie::video {

// Whether an RTP payload of H.264 (RFC 6184) or H.265 (RFC 7798) is whole enough for GStreamer
// 1.22's depayloaders: they crash on some cut-short aggregation and fragmentation units
// (tst_videoreceiver's truncated stream: rtph264depay dereferences an empty adapter), so the
// receiver drops such packets before them. Accepted: single NAL units of at least one byte, STAP-A /
// AP whose every unit fits, FU-A / FU of at least one byte of data. Refused: empty payloads, the
// interleaved modes (STAP-B, MTAP, FU-B, which no camera in non-interleaved mode sends) and
// anything cut short.
bool plausibleH264Payload(const uchar *payload, int size);
bool plausibleH265Payload(const uchar *payload, int size);

} // namespace sortie::video
