#pragma once

#include "HciTrafficSource.h"
#include "SbsFeed.h"
#include "TrafficPicture.h"

#include <QObject>
#include <QString>

#include <memory>

class QSettings;

namespace sortie::hci {
class HciClient;
}

namespace sortie::traffic {

// The manned traffic of one client: the picture and its two sources, an ADS-B receiver's SBS-1 feed
// (its address is the setting traffic/sbsAddress, unless the program gives one) and the UgCS
// server's list around the view the map shows (lookAt). Built by the client graph.
class Traffic : public QObject
{
    Q_OBJECT
    Q_PROPERTY(sortie::traffic::TrafficPicture *picture READ picture CONSTANT)
    Q_PROPERTY(sortie::traffic::SbsFeed *receiver READ receiver CONSTANT)
    Q_PROPERTY(sortie::traffic::HciTrafficSource *server READ server CONSTANT)
    // The receiver's host:port as the operator set it (remembered); empty: no receiver.
    Q_PROPERTY(QString receiverAddress READ receiverAddress WRITE setReceiverAddress NOTIFY receiverAddressChanged)

public:
    static constexpr const char *kAddressSetting = "traffic/sbsAddress";
    // The most aircraft held (TrafficPicture::setCapacity), the nearest to the view; default 500.
    static constexpr const char *kCapacitySetting = "traffic/maxAircraft";

    // `storage` (not owned) keeps the receiver's address; `addressOverride`, when not empty, is used
    // instead of the setting and not written to it (sortie --demo, --sbs). `clock`: the picture's
    // (tests age aircraft with their own); default the system clock.
    Traffic(QSettings *storage, hci::HciClient *client, const QString &addressOverride = {}, TrafficPicture::Clock clock = {},
            QObject *parent = nullptr);
    ~Traffic() override;

    TrafficPicture *picture() const { return m_picture.get(); }
    SbsFeed *receiver() const { return m_receiver.get(); }
    HciTrafficSource *server() const { return m_server.get(); }
    QString receiverAddress() const;
    void setReceiverAddress(const QString &address);

    // The view the operator sees: the server is asked about this circle (degrees, metres), and the
    // picture keeps the aircraft nearest its centre when full.
    Q_INVOKABLE void lookAt(double latitude, double longitude, double radiusM);

signals:
    void receiverAddressChanged();

private:
    QSettings *m_storage;
    std::unique_ptr<TrafficPicture> m_picture;
    std::unique_ptr<SbsFeed> m_receiver;
    std::unique_ptr<HciTrafficSource> m_server;
};

} // namespace sortie::traffic
