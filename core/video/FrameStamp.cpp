#include "FrameStamp.h"

#include <chrono>
#include <cstring>

namespace sortie::video::FrameStamp {
namespace {

constexpr quint8 kSync = 0b10110010;

quint8 check(quint64 value)
{
    quint8 x = 0x5A;
    for (int i = 0; i < 8; ++i)
        x ^= quint8(value >> (8 * i));
    return x;
}

// The 80 bits of the row, block 0 first.
bool bit(int block, quint64 value)
{
    if (block < 8)
        return (kSync >> (7 - block)) & 1;
    if (block < 72)
        return (value >> (63 - (block - 8))) & 1;
    return (check(value) >> (7 - (block - 72))) & 1;
}

} // namespace

int blockSize(int width)
{
    const int size = width / kColumns;
    return size >= 4 ? size : 0;
}

int height(int width)
{
    return 2 * blockSize(width);
}

void write(uchar *luma, int stride, int width, int height, quint64 value)
{
    const int size = blockSize(width);
    if (size == 0 || height < 2 * size)
        return;
    for (int y = 0; y < 2 * size; ++y) {
        uchar *row = luma + qsizetype(y) * stride;
        std::memset(row, kBlack, size_t(width));
        const int first = (y / size) * kColumns;
        for (int c = 0; c < kColumns; ++c)
            if (bit(first + c, value))
                std::memset(row + c * size, kWhite, size_t(size));
    }
}

std::optional<quint64> read(const QImage &image)
{
    const int size = blockSize(image.width());
    if (size == 0 || image.height() < 2 * size)
        return std::nullopt;
    // The mean of the block's inner half, away from the edges the encoder blurs.
    const auto blockBit = [&](int b) {
        const int x0 = (b % kColumns) * size + size / 4, y0 = (b / kColumns) * size + size / 4;
        int sum = 0, n = 0;
        for (int y = y0; y < y0 + size / 2; ++y)
            for (int x = x0; x < x0 + size / 2; ++x, ++n)
                sum += qGray(image.pixel(x, y));
        return sum / n > 128;
    };
    quint8 sync = 0;
    for (int b = 0; b < 8; ++b)
        sync = quint8((sync << 1) | (blockBit(b) ? 1 : 0));
    if (sync != kSync)
        return std::nullopt;
    quint64 value = 0;
    for (int b = 8; b < 72; ++b)
        value = (value << 1) | (blockBit(b) ? 1 : 0);
    quint8 got = 0;
    for (int b = 72; b < 80; ++b)
        got = quint8((got << 1) | (blockBit(b) ? 1 : 0));
    if (got != check(value))
        return std::nullopt;
    return value;
}

qint64 nowMicros()
{
    using namespace std::chrono;
    return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

} // namespace sortie::video::FrameStamp
