#pragma once

#include <QImage>
#include <QtGlobal>

#include <optional>

namespace sortie::video {

// A 64-bit number (sortie-sim's capture time, microseconds since the epoch) drawn into the top of a
// picture as a row of black and white blocks, and read back from the decoded frame: how the latency
// is measured glass to glass (docs/video.md, "The stamp"). Two rows of kColumns square blocks across
// the width (32 px at 1280, two macroblocks, so even a starved encoder keeps them apart): 8 blocks of
// a fixed pattern, the 64 bits most significant first, 8 bits of check (the XOR of the value's bytes
// and 0x5A). A frame whose rows do not read back whole has no stamp (nullopt), never a wrong one.
namespace FrameStamp {

constexpr int kBlocks = 80;   // 8 + 64 + 8 bits
constexpr int kColumns = 40;  // in two rows
constexpr quint8 kBlack = 16;   // video-range luma
constexpr quint8 kWhite = 235;

// The block's side for a picture this wide (0 when narrower than 4 px per block: no stamp fits).
int blockSize(int width);
// The rows the stamp takes at the top of the picture (two blocks).
int height(int width);
// Draws `value` into the rows [0, height) of an 8-bit luma plane.
void write(uchar *luma, int stride, int width, int height, quint64 value);
// Reads the stamp of a decoded picture (any format QImage can give a pixel's grey of).
std::optional<quint64> read(const QImage &image);
// The clock the stamp holds: microseconds since the epoch (CLOCK_REALTIME, one clock on one machine).
qint64 nowMicros();

} // namespace FrameStamp
} // namespace sortie::video
