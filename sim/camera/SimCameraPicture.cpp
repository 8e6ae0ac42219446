#include "SimCameraPicture.h"

#include "FrameStamp.h"

#include <algorithm>
#include <cmath>

namespace sortie::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kOriginLatitude = 56.95, kOriginLongitude = 24.1;
constexpr double kMetresPerDegree = 111'320.0;

} // namespace

SimCameraPicture::SimCameraPicture(int width, int height)
    : m_width(width & ~1)
    , m_height(height & ~1)
{
}

qsizetype SimCameraPicture::frameBytes() const
{
    return qsizetype(m_width) * m_height * 3 / 2;
}

void SimCameraPicture::draw(uchar *i420, const CameraPose &pose) const
{
    const int w = m_width, h = m_height;
    uchar *yPlane = i420;
    uchar *uPlane = yPlane + qsizetype(w) * h;
    uchar *vPlane = uPlane + qsizetype(w / 2) * (h / 2);
    const double east0 = (pose.longitude - kOriginLongitude) * kMetresPerDegree * std::cos(pose.latitude * kPi / 180);
    const double north0 = (pose.latitude - kOriginLatitude) * kMetresPerDegree;
    const double heading = pose.heading * kPi / 180;
    // A 60° lens: the picture's width covers 1.15 × the height above the ground (40 m at least, so
    // a parked vehicle sees a few fields, as a camera on a mast would).
    const double metresPerPixel = std::max(40.0, pose.altitudeAgl) * 1.15 / w;
    const double c = std::cos(heading), s = std::sin(heading);
    // Right of the picture: (cos h, -sin h) in (east, north); up: (sin h, cos h).
    const auto ground = [&](double px, double py, double *east, double *north) {
        const double dx = (px - w / 2.0) * metresPerPixel, dy = (h / 2.0 - py) * metresPerPixel;
        *east = east0 + dx * c + dy * s;
        *north = north0 - dx * s + dy * c;
    };
    for (int y = 0; y < h; ++y) {
        double east, north;
        ground(0, y, &east, &north);
        const double stepEast = c * metresPerPixel, stepNorth = -s * metresPerPixel;
        uchar *row = yPlane + qsizetype(y) * w;
        for (int x = 0; x < w; ++x, east += stepEast, north += stepNorth) {
            const long fe = long(std::floor(east / 5)), fn = long(std::floor(north / 5));
            const bool road = (((fe % 10) + 10) % 10 == 0) || (((fn % 10) + 10) % 10 == 0);
            row[x] = road ? 70 : (((fe + fn) & 1) ? 150 : 110) + uchar((fe * 7 + fn * 13) & 31);
        }
    }
    for (int y = 0; y < h / 2; ++y) {
        double east, north;
        ground(1, 2 * y + 1, &east, &north);
        const double stepEast = 2 * c * metresPerPixel, stepNorth = -2 * s * metresPerPixel;
        uchar *u = uPlane + qsizetype(y) * (w / 2), *v = vPlane + qsizetype(y) * (w / 2);
        for (int x = 0; x < w / 2; ++x, east += stepEast, north += stepNorth) {
            const long fe = long(std::floor(east / 5)), fn = long(std::floor(north / 5));
            const bool grass = ((fe + fn) & 1) != 0;
            u[x] = grass ? 100 : 112;  // green fields and brown ones
            v[x] = grass ? 110 : 140;
        }
    }
    // The centre cross.
    for (int d = -20; d <= 20; ++d) {
        yPlane[qsizetype(h / 2) * w + w / 2 + d] = 235;
        yPlane[qsizetype(h / 2 + d) * w + w / 2] = 235;
    }
    // Grey chroma under the stamp's rows, so it decodes to black and white.
    const int rows = video::FrameStamp::height(w) / 2 + 1;
    for (int y = 0; y < rows && y < h / 2; ++y) {
        std::fill_n(uPlane + qsizetype(y) * (w / 2), w / 2, uchar(128));
        std::fill_n(vPlane + qsizetype(y) * (w / 2), w / 2, uchar(128));
    }
}

void SimCameraPicture::stamp(uchar *i420, quint64 captureUs) const
{
    video::FrameStamp::write(i420, m_width, m_width, m_height, captureUs);
}

} // namespace sortie::sim
