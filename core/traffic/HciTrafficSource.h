#pragma once

#include "TrafficReport.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

namespace com::ugcs::ucs::proto {
class AdsbAircraft;
}

namespace sortie::hci {
class HciClient;
class HciReply;
} // namespace sortie::hci

namespace sortie::traffic {

class TrafficPicture;

// The ADS-B aircraft the UgCS server knows around the map's view (GetAdsbAircraftListRequest), into
// the picture: asked when signed in and an area is set, then every kRefreshMs, one request at a
// time (a slow server is not asked again before it answered). A failure is shown (state, error)
// and the next refresh asks again.
class HciTrafficSource : public QObject
{
    Q_OBJECT
    Q_PROPERTY(State state READ state NOTIFY stateChanged)
    Q_PROPERTY(QString error READ error NOTIFY stateChanged)
    Q_PROPERTY(int lastCount READ lastCount NOTIFY stateChanged) // aircraft in the last answer

public:
    enum class State { Idle, Asking, Answered, Failed };
    Q_ENUM(State)
    static constexpr int kRefreshMs = 2000;
    static constexpr double kMinRadiusM = 2000;
    static constexpr double kMaxRadiusM = 200000;
    static constexpr double kHeightM = 20000; // how high above the area the server is asked to look

    HciTrafficSource(hci::HciClient *client, TrafficPicture *picture, QObject *parent = nullptr);

    // The area to ask about: a centre (degrees) and a radius in metres, clamped to the limits above.
    void setArea(double latitude, double longitude, double radiusM);
    bool hasArea() const { return m_hasArea; }
    double radiusM() const { return m_radiusM; }
    // Asks now (when signed in, with an area, and no request outstanding).
    void refresh();

    State state() const { return m_state; }
    QString error() const { return m_error; }
    int lastCount() const { return m_lastCount; }

    // One server entry as a report; nullopt without an address. Lat/lon and heading are radians in
    // HCI, as everywhere there; fields that are not finite are left out.
    static std::optional<TrafficReport> reportFromAdsb(const com::ugcs::ucs::proto::AdsbAircraft &aircraft);

signals:
    void stateChanged();
    void answered(); // after each answer went into the picture (tests)

private:
    void onFinished(hci::HciReply *reply);
    void setState(State state, const QString &error = {});

    hci::HciClient *m_client;
    TrafficPicture *m_picture;
    QTimer m_timer;
    QPointer<hci::HciReply> m_pending;
    bool m_hasArea = false;
    double m_latitude = 0, m_longitude = 0, m_radiusM = kMinRadiusM;
    State m_state = State::Idle;
    QString m_error;
    int m_lastCount = 0;
};

} // namespace sortie::traffic
