#pragma once

#include <QObject>
#include <QQuaternion>
#include <QVector3D>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// The 3D view's camera as a point it orbits: the target (scene metres, SceneFrame's axes), the
// distance to it, the heading it looks towards (degrees clockwise from north) and how far it looks
// down (degrees below the horizon, 5..89). The view's PerspectiveCamera binds `position` and
// `rotation`; the mouse and keys call the gestures below. Only a gesture changes it, so an idle
// view asks for no frame.
class OrbitCamera : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("FlightScene's camera")
    Q_PROPERTY(QVector3D target READ target WRITE setTarget NOTIFY changed)
    Q_PROPERTY(double distance READ distance WRITE setDistance NOTIFY changed)
    Q_PROPERTY(double heading READ heading WRITE setHeading NOTIFY changed)
    Q_PROPERTY(double tilt READ tilt WRITE setTilt NOTIFY changed)
    Q_PROPERTY(double fieldOfView READ fieldOfView CONSTANT)  // vertical, degrees
    Q_PROPERTY(QVector3D position READ position NOTIFY changed)
    Q_PROPERTY(QQuaternion rotation READ rotation NOTIFY changed)
    Q_PROPERTY(double clipNear READ clipNear NOTIFY changed)
    Q_PROPERTY(double clipFar READ clipFar NOTIFY changed)

public:
    explicit OrbitCamera(QObject *parent = nullptr);

    QVector3D target() const { return m_target; }
    void setTarget(const QVector3D &target);
    double distance() const { return m_distance; }
    void setDistance(double metres);
    double heading() const { return m_heading; }
    void setHeading(double degrees);
    double tilt() const { return m_tilt; }
    void setTilt(double degrees);
    double fieldOfView() const { return m_fov; }

    QVector3D forward() const;  // unit vector the camera looks along
    QVector3D position() const { return m_target - forward() * float(m_distance); }
    QQuaternion rotation() const;
    double clipNear() const;
    double clipFar() const;

    // The ray through a pixel of a w×h view: its direction (unit) from position().
    QVector3D rayThrough(double x, double y, double width, double height) const;

    // Mouse gestures (pixels) and keys.
    Q_INVOKABLE void orbit(double dxPixels, double dyPixels);
    Q_INVOKABLE void pan(double dxPixels, double dyPixels, double viewHeight);
    // factor < 1 zooms in, > 1 out, about the point under the pixel (on the target's level), which stays under it.
    Q_INVOKABLE void zoomAt(double x, double y, double width, double height, double factor);
    Q_INVOKABLE void turn(double degrees) { setHeading(m_heading + degrees); }
    Q_INVOKABLE void tiltBy(double degrees) { setTilt(m_tilt + degrees); }
    // The 2D map's keys: arrows pan (Shift: four times as far), + and - zoom; and Page Up / Down
    // tilt, [ and ] turn. False for any other key.
    Q_INVOKABLE bool key(int key, int modifiers, double viewHeight);
    // Everything between two corners in view, looked at from the current heading and tilt.
    void fit(const QVector3D &minimum, const QVector3D &maximum);

signals:
    void changed();

private:
    QVector3D m_target;
    double m_distance = 3000.0;
    double m_heading = 0.0;
    double m_tilt = 45.0;
    double m_fov = 45.0;
};

} // namespace sortie::ui
