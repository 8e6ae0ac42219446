#pragma once

#include <QString>

namespace sortie::video {

// The Debian 12 package that holds a GStreamer element Sortie needs, so a missing one is named to
// the operator ("install gstreamer1.0-libav"), never a blank picture. Empty for an element we do
// not know.
QString debianPackageOfElement(const QString &element);
// The package that decodes these caps ("video/x-h264", "video/x-h265", ...).
QString debianPackageOfDecoder(const QString &capsName);

} // namespace sortie::video
