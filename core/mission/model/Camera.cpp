#include "Camera.h"
#include <QCoreApplication>

namespace sortie::mission {

const std::vector<Camera> &builtInCameras()
{
    // Sensor width × height (mm), focal length (mm), pixels, shortest interval (s) where published.
    static const std::vector<Camera> cameras{
        {QCoreApplication::translate("Camera", "DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)"), 13.2, 8.8, 8.8, 5472, 3648, 0.0},
        {QCoreApplication::translate("Camera", "DJI Phantom 4 (FC330)"), 6.17, 4.55, 3.61, 4000, 3000, 0.0},
        {QCoreApplication::translate("Camera", "DJI Mavic 2 Pro (Hasselblad L1D-20c)"), 13.2, 8.8, 10.26, 5472, 3648, 0.0},
        {QCoreApplication::translate("Camera", "DJI Mavic 3 Enterprise (wide)"), 17.3, 13.0, 12.29, 5280, 3956, 0.7},
        {QCoreApplication::translate("Camera", "DJI Zenmuse P1 24 mm"), 35.9, 24.0, 24.0, 8192, 5460, 0.7},
        {QCoreApplication::translate("Camera", "DJI Zenmuse P1 35 mm"), 35.9, 24.0, 35.0, 8192, 5460, 0.7},
        {QCoreApplication::translate("Camera", "Sony RX1R II"), 35.9, 24.0, 35.0, 7952, 5304, 0.0},
        {QCoreApplication::translate("Camera", "senseFly S.O.D.A."), 13.2, 8.8, 10.6, 5472, 3648, 0.0},
        {QCoreApplication::translate("Camera", "MicaSense RedEdge-MX"), 4.8, 3.6, 5.4, 1280, 960, 1.0},
        {QCoreApplication::translate("Camera", "GoPro Hero3 Black Edition"), 6.17, 4.55, 2.8, 4000, 3000, 1.0},
    };
    return cameras;
}

std::optional<Camera> builtInCamera(const QString &name)
{
    for (const Camera &c : builtInCameras())
        if (c.name == name)
            return c;
    return std::nullopt;
}

std::optional<Camera> resolveCamera(const QString &value, const std::vector<ProfileCamera> &cameras)
{
    const QString v = value.trimmed();
    if (v.isEmpty())
        return cameras.empty() ? std::nullopt : std::optional<Camera>(cameras.front().camera);
    bool numeric = false;
    const int id = v.toInt(&numeric);
    for (const ProfileCamera &c : cameras)
        if ((numeric && c.id == id) || c.camera.name == v)
            return c.camera;
    return builtInCamera(v);
}

} // namespace sortie::mission
