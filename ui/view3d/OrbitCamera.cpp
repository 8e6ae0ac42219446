#include "OrbitCamera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::ui {

namespace {
constexpr double kRadians = std::numbers::pi / 180.0;
}

OrbitCamera::OrbitCamera(QObject *parent) : QObject(parent) {}

void OrbitCamera::setTarget(const QVector3D &target)
{
    if (target == m_target || !std::isfinite(target.x()) || !std::isfinite(target.y()) || !std::isfinite(target.z()))
        return;
    m_target = target;
    emit changed();
}

void OrbitCamera::setDistance(double metres)
{
    metres = std::clamp(metres, 5.0, 500000.0);
    if (!std::isfinite(metres) || metres == m_distance)
        return;
    m_distance = metres;
    emit changed();
}

void OrbitCamera::setHeading(double degrees)
{
    if (!std::isfinite(degrees))
        return;
    degrees = std::fmod(degrees, 360.0);
    if (degrees < 0)
        degrees += 360.0;
    if (degrees == m_heading)
        return;
    m_heading = degrees;
    emit changed();
}

void OrbitCamera::setTilt(double degrees)
{
    if (!std::isfinite(degrees))
        return;
    degrees = std::clamp(degrees, 5.0, 89.0);
    if (degrees == m_tilt)
        return;
    m_tilt = degrees;
    emit changed();
}

QVector3D OrbitCamera::forward() const
{
    const double h = m_heading * kRadians, t = m_tilt * kRadians;
    // heading 0 looks north (-z), 90 east (+x)
    return QVector3D(float(std::sin(h) * std::cos(t)), float(-std::sin(t)), float(-std::cos(h) * std::cos(t)));
}

QQuaternion OrbitCamera::rotation() const
{
    // Qt Quick 3D's camera looks along -z: pitch down by the tilt, then turn to the heading.
    return QQuaternion::fromEulerAngles(float(-m_tilt), float(-m_heading), 0.0f);
}

double OrbitCamera::clipNear() const
{
    return std::max(1.0, m_distance / 200.0);
}

double OrbitCamera::clipFar() const
{
    return m_distance * 20.0 + 60000.0;
}

QVector3D OrbitCamera::rayThrough(double x, double y, double width, double height) const
{
    const QQuaternion q = rotation();
    const QVector3D f = q.rotatedVector(QVector3D(0, 0, -1));
    const QVector3D right = q.rotatedVector(QVector3D(1, 0, 0));
    const QVector3D up = q.rotatedVector(QVector3D(0, 1, 0));
    const double halfH = std::tan(m_fov * kRadians / 2.0);
    const double halfW = halfH * (height > 0 ? width / height : 1.0);
    const double nx = width > 0 ? (2.0 * x / width - 1.0) : 0.0;
    const double ny = height > 0 ? (1.0 - 2.0 * y / height) : 0.0;
    return (f + right * float(nx * halfW) + up * float(ny * halfH)).normalized();
}

void OrbitCamera::orbit(double dxPixels, double dyPixels)
{
    const double heading = m_heading - dxPixels * 0.3, tilt = std::clamp(m_tilt + dyPixels * 0.2, 5.0, 89.0);
    if (heading == m_heading && tilt == m_tilt)
        return;
    m_heading = std::fmod(heading + 360.0, 360.0);
    m_tilt = tilt;
    emit changed();
}

void OrbitCamera::pan(double dxPixels, double dyPixels, double viewHeight)
{
    const double metresPerPixel = 2.0 * m_distance * std::tan(m_fov * kRadians / 2.0) / std::max(viewHeight, 1.0);
    const double h = m_heading * kRadians;
    const QVector3D right(float(std::cos(h)), 0.0f, float(std::sin(h)));
    const QVector3D ahead(float(std::sin(h)), 0.0f, float(-std::cos(h)));
    // the ground follows the mouse: dragging right moves the target left
    setTarget(m_target - right * float(dxPixels * metresPerPixel) + ahead * float(dyPixels * metresPerPixel / std::sin(m_tilt * kRadians)));
}

void OrbitCamera::zoomAt(double x, double y, double width, double height, double factor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    const double distance = std::clamp(m_distance * factor, 5.0, 500000.0);
    factor = distance / m_distance;
    const QVector3D from = position();
    const QVector3D ray = rayThrough(x, y, width, height);
    QVector3D hit = m_target;
    if (ray.y() < -1e-4f) {
        const float t = (m_target.y() - from.y()) / ray.y();
        hit = from + ray * t;
    }
    // scaled about the point under the cursor: it stays under it
    m_target = hit + (m_target - hit) * float(factor);
    m_distance = distance;
    emit changed();
}

bool OrbitCamera::key(int key, int modifiers, double viewHeight)
{
    const double step = 60.0 * ((modifiers & Qt::ShiftModifier) ? 4 : 1);
    switch (key) {
    case Qt::Key_Left: pan(step, 0, viewHeight); break;
    case Qt::Key_Right: pan(-step, 0, viewHeight); break;
    case Qt::Key_Up: pan(0, step, viewHeight); break;
    case Qt::Key_Down: pan(0, -step, viewHeight); break;
    case Qt::Key_Plus:
    case Qt::Key_Equal: setDistance(m_distance / 1.5); break;
    case Qt::Key_Minus:
    case Qt::Key_Underscore: setDistance(m_distance * 1.5); break;
    case Qt::Key_PageUp: tiltBy(5); break;
    case Qt::Key_PageDown: tiltBy(-5); break;
    case Qt::Key_BracketLeft: turn(-10); break;
    case Qt::Key_BracketRight: turn(10); break;
    default: return false;
    }
    return true;
}

void OrbitCamera::fit(const QVector3D &minimum, const QVector3D &maximum)
{
    const QVector3D centre = (minimum + maximum) / 2.0f;
    const double radius = std::max(double((maximum - minimum).length()) / 2.0, 50.0);
    m_target = centre;
    m_distance = std::clamp(radius / std::sin(m_fov * kRadians / 2.0) * 0.9, 5.0, 500000.0);
    emit changed();
}

} // namespace sortie::ui
