#include "HistoryPages.h"

#include "HciTelemetryMapper.h"
#include "Messages.pb.h"
#include "TelemetryBlockCodec.h"

#include <QString>

#include <algorithm>
#include <array>

namespace sortie::flightlog {

namespace pb = com::ugcs::ucs::proto;

HistoryPages::HistoryPages(int64_t fromMs, int64_t toMs)
    : m_from(fromMs)
    , m_to(std::max(fromMs, toMs))
    , m_next(fromMs)
{
}

std::optional<int64_t> HistoryPages::add(const pb::GetTelemetryResponse &page, int64_t receivedAtMs)
{
    const size_t before = m_updates.size();
    for (const pb::Telemetry &t : page.telemetry())
        vehicle::appendHciTelemetry(t, receivedAtMs, m_updates);
    // A value outside the range asked for is the server's mistake; it would stretch the log.
    const auto outside = std::remove_if(m_updates.begin() + std::ptrdiff_t(before), m_updates.end(),
                                        [this](const vehicle::TelemetryUpdate &u) { return u.time < m_from || u.time > m_to; });
    m_outOfRange += size_t(m_updates.end() - outside);
    m_updates.erase(outside, m_updates.end());

    // Go on from where the server says, as long as that moves forward within the range.
    std::optional<int64_t> next;
    if (page.has_nexttelemetrytime() && page.telemetry_size() > 0 && page.nexttelemetrytime() > m_next
        && page.nexttelemetrytime() <= m_to)
        next = page.nexttelemetrytime();
    m_progress = !next || m_to <= m_from ? 1.0 : double(*next - m_from) / double(m_to - m_from);
    if (next)
        m_next = *next;
    return next;
}

std::unique_ptr<FlightLog> HistoryPages::takeLog(const pb::Vehicle &vehicle)
{
    std::stable_sort(m_updates.begin(), m_updates.end(), [](const auto &a, const auto &b) { return a.time < b.time; });
    FlightLog::Vehicle v;
    v.key = QStringLiteral("HCI:%1").arg(vehicle.id());
    v.identity.id = QString::number(vehicle.id());
    v.identity.name = QString::fromStdString(vehicle.name());
    v.identity.protocol = QStringLiteral("HCI");
    BlockFields fields;
    std::array<int, vehicle::kTelemetryFieldCount> slot;
    slot.fill(-1);
    int64_t blockStart = 0;
    auto close = [&] {
        if (!fields.empty())
            v.appendBlock(TelemetryBlockCodec::encode(fields));
        fields.clear();
        slot.fill(-1);
    };
    // Every time is inside [from, to] (add), so the differences below cannot overflow.
    for (const vehicle::TelemetryUpdate &u : m_updates) {
        if (!fields.empty() && u.time - blockStart >= 1000)
            close();
        if (fields.empty())
            blockStart = u.time;
        int &s = slot[size_t(u.field)];
        if (s < 0) {
            s = int(fields.size());
            fields.push_back({u.field, {}});
        }
        fields[size_t(s)].samples.push_back({u.time, u.value});
    }
    close();
    m_updates.clear();
    m_updates.shrink_to_fit();
    auto log = std::make_unique<FlightLog>();
    log->addVehicle(std::move(v));
    log->finish();
    return log;
}

} // namespace sortie::flightlog
