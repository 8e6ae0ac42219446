#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace google::protobuf {
class Descriptor;
}

namespace sortie::hci {

// The most memory one HCI frame may decode into. A frame may be 64 MiB on the wire, and protobuf's
// wire format lets two bytes (an empty sub-message) become an object of 50 bytes or more, so a
// frame of repeated empty messages would expand tens of times; real frames (routes, elevation
// grids, vehicle lists) stay within a few times their size.
inline constexpr size_t kHciMaxDecodedBytes = size_t(256) << 20;

// Frames smaller than this are not pre-scanned: even at protobuf's worst expansion they decode into
// a few tens of MiB, and telemetry (thousands of frames a second) stays on its fast path.
inline constexpr size_t kHciPrescanFromBytes = size_t(1) << 20;

// Estimates the bytes parsing `wire` as a `type` message would allocate, walking the wire format
// without allocating: one object per sub-message (its type's own size), strings and bytes at
// their length, scalars at eight bytes an element, unknown fields at their length. The walk stops
// as soon as the estimate passes `limit` (it then returns a value above `limit`). Nothing when the
// bytes are not a well-formed message of that type, nested deeper than protobuf's own limit of
// 100 included: the parser then refuses them with its own reason.
std::optional<size_t> estimateDecodedBytes(std::string_view wire, const google::protobuf::Descriptor &type,
                                           size_t limit = kHciMaxDecodedBytes);

} // namespace sortie::hci
