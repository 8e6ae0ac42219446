#pragma once

#include "FlightLog.h"
#include "HciReply.h"

#include <QObject>
#include <QPointer>

#include <memory>

namespace com::ugcs::ucs::proto {
class Vehicle;
}
namespace sortie::hci {
class HciClient;
}

namespace sortie::flightlog {

class HistoryPages;

// The server's telemetry history of one vehicle between two times (GetTelemetryRequest), fetched
// page by page (the server answers at most `limit` values and says where to go on), with progress,
// and turned into a FlightLog the replay plays like a recorded one (HistoryPages: what is done with
// each page).
class ServerHistory : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool busy READ isBusy NOTIFY busyChanged)
    Q_PROPERTY(double progress READ progress NOTIFY progressChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY finished)

public:
    explicit ServerHistory(hci::HciClient *client, QObject *parent = nullptr);
    ~ServerHistory() override;

    void fetch(const com::ugcs::ucs::proto::Vehicle &vehicle, qint64 fromMs, qint64 toMs, int pageLimit = 7200);
    Q_INVOKABLE void cancel();

    bool isBusy() const { return m_reply != nullptr; }
    double progress() const { return m_progress; } // 0..1 of the time range
    QString errorString() const { return m_error; }
    int pages() const { return m_pageCount; }
    // The log once finished(true); the caller takes it.
    std::unique_ptr<FlightLog> takeLog();

signals:
    void busyChanged();
    void progressChanged();
    void finished(bool ok);

private:
    void request(qint64 fromMs);
    void onReply();
    void finish(bool ok, const QString &error = {});

    QPointer<hci::HciClient> m_client;
    std::unique_ptr<com::ugcs::ucs::proto::Vehicle> m_vehicle;
    qint64 m_to = 0;
    int m_limit = 7200;
    QPointer<hci::HciReply> m_reply;
    std::unique_ptr<HistoryPages> m_pages;  // while fetching
    std::unique_ptr<FlightLog> m_log;
    double m_progress = 0;
    int m_pageCount = 0;
    QString m_error;
};

} // namespace sortie::flightlog
