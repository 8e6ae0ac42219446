#pragma once

#include <QMetaObject>

namespace sortie::client {
class MissionUploader;
}

namespace sortie::airspace {

class ZoneAlertMonitor;

// A vehicle is warned of the fence that went up with its mission: each upload's route fence becomes
// that vehicle's own zones in the zone alerts (beside the airspace every vehicle is warned of). The
// client graph makes one per uploader.
class UploadedFenceAlerts
{
public:
    // Both must outlive this object.
    UploadedFenceAlerts(client::MissionUploader *uploader, ZoneAlertMonitor *alerts);
    ~UploadedFenceAlerts();
    UploadedFenceAlerts(const UploadedFenceAlerts &) = delete;
    UploadedFenceAlerts &operator=(const UploadedFenceAlerts &) = delete;

    // Whether uploads reach the alerts (for the graph's wiring lines).
    bool isFollowing() const { return bool(m_uploads); }

private:
    QMetaObject::Connection m_uploads;
};

} // namespace sortie::airspace
