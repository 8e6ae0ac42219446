#pragma once

#include <QtGlobal>

namespace sortie::sim {

// Where the camera is: the vehicle's position and heading (it looks straight down, the top of the
// picture ahead), and its height for the scale.
struct CameraPose
{
    double latitude = 56.95, longitude = 24.1;  // degrees
    double heading = 0;                         // degrees, clockwise from north
    double altitudeAgl = 50;                    // metres
};

// Draws the synthetic view into an I420 frame: fields of 5 m squares and a road every 50 m, seen
// from above, moving and turning with the vehicle, a cross at the centre; and, last, the capture
// time stamped into the top row by stamp() (core/video's FrameStamp). No text: the picture is the same in
// every language.
class SimCameraPicture
{
public:
    SimCameraPicture(int width, int height);
    int width() const { return m_width; }
    int height() const { return m_height; }
    qsizetype frameBytes() const;
    // Fills `i420` (frameBytes() long).
    void draw(uchar *i420, const CameraPose &pose) const;
    // Stamps the capture time into its top row.
    void stamp(uchar *i420, quint64 captureUs) const;

private:
    int m_width;
    int m_height;
};

} // namespace sortie::sim
