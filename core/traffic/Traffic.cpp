#include "Traffic.h"

#include "HciTrafficSource.h"
#include "SbsFeed.h"
#include "TrafficPicture.h"

#include <QSettings>

namespace sortie::traffic {

Traffic::Traffic(QSettings *storage, hci::HciClient *client, const QString &addressOverride, TrafficPicture::Clock clock, QObject *parent)
    : QObject(parent)
    , m_storage(storage)
    , m_picture(std::make_unique<TrafficPicture>(std::move(clock)))
    , m_receiver(std::make_unique<SbsFeed>(m_picture.get()))
    , m_server(std::make_unique<HciTrafficSource>(client, m_picture.get()))
{
    const QString address = addressOverride.isEmpty() && storage ? storage->value(QLatin1String(kAddressSetting)).toString()
                                                                 : addressOverride;
    m_receiver->setAddress(address);
    // How many aircraft the picture holds at most (the nearest to the view): a number of at least 1.
    bool ok = false;
    const int capacity = storage ? storage->value(QLatin1String(kCapacitySetting)).toInt(&ok) : 0;
    m_picture->setCapacity(ok && capacity >= 1 ? capacity : TrafficPicture::kDefaultCapacity);
}

Traffic::~Traffic() = default;

QString Traffic::receiverAddress() const
{
    return m_receiver->address();
}

void Traffic::setReceiverAddress(const QString &address)
{
    if (address.trimmed() == m_receiver->address())
        return;
    if (m_receiver->setAddress(address) && m_storage)
        m_storage->setValue(QLatin1String(kAddressSetting), address.trimmed());
    emit receiverAddressChanged();
}

void Traffic::lookAt(double latitude, double longitude, double radiusM)
{
    m_server->setArea(latitude, longitude, radiusM);
    m_picture->setReference(latitude, longitude);
}

} // namespace sortie::traffic
