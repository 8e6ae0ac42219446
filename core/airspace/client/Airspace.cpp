#include "Airspace.h"

#include "AirspaceRule.h"
#include "CustomZoneFile.h"
#include "RouteAnalyzer.h"
#include "RouteModel.h"
#include "ZoneEditor.h"
#include "ZoneFiles.h"
#include "ZoneListModel.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QGeoCoordinate>
#include <QLoggingCategory>
#include <QSettings>
#include <QTimeZone>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcAirspace, "sortie.airspace")

namespace sortie::airspace {

namespace {
const QString kBufferKey = QStringLiteral("airspace/buffer");
const QString kFilesKey = QStringLiteral("airspace/zoneFiles");
// A feed's copy -> "<fetched, ISO 8601 UTC> <url>".
const QString kFeedsKey = QStringLiteral("airspace/feeds");

struct FeedRecord
{
    QUrl url;
    QDateTime fetched;
};

std::optional<FeedRecord> feedRecordOf(const QSettings &settings, const QString &copy)
{
    const QString value = settings.value(kFeedsKey).toMap().value(copy).toString();
    const qsizetype space = value.indexOf(QLatin1Char(' '));
    if (space <= 0)
        return std::nullopt;
    FeedRecord r{QUrl(value.mid(space + 1)), QDateTime::fromString(value.left(space), Qt::ISODate)};
    return r.url.isValid() && r.fetched.isValid() ? std::optional(r) : std::nullopt;
}

// "today", "yesterday", "9 days ago".
QString daysAgo(const QDateTime &then, const QDateTime &now)
{
    const qint64 days = then.daysTo(now);
    return days <= 0 ? QCoreApplication::translate("Airspace", "today")
         : days == 1 ? QCoreApplication::translate("Airspace", "yesterday")
                     : QCoreApplication::translate("Airspace", "%n day(s) ago", nullptr, int(days));
}

// The flown path between two distances from the route's start along one leg: the leg's own points
// between them and the two ends interpolated (pieces are short and straight).
std::vector<mission::GeoPoint> stretchOf(const FlownPath &path, int legNumber, double from, double to)
{
    std::vector<mission::GeoPoint> out;
    const auto leg = std::find_if(path.legs.begin(), path.legs.end(), [&](const FlownLeg &l) { return l.leg == legNumber; });
    if (leg == path.legs.end() || leg->points.empty())
        return out;
    const auto at = [&](double d) {
        const double along = d - leg->start;
        const std::vector<FlownPoint> &p = leg->points;
        for (size_t i = 1; i < p.size(); ++i)
            if (along <= p[i].along || i + 1 == p.size()) {
                const double span = p[i].along - p[i - 1].along;
                const double t = span > 0 ? std::clamp((along - p[i - 1].along) / span, 0.0, 1.0) : 0.0;
                return mission::GeoPoint{p[i - 1].position.latitude + t * (p[i].position.latitude - p[i - 1].position.latitude),
                                         p[i - 1].position.longitude + t * (p[i].position.longitude - p[i - 1].position.longitude)};
            }
        return p.front().position;
    };
    out.push_back(at(from));
    for (const FlownPoint &p : leg->points)
        if (leg->start + p.along > from && leg->start + p.along < to)
            out.push_back(p.position);
    out.push_back(at(to));
    return out;
}
} // namespace

Airspace::Airspace(QSettings *settings, mission::RouteAnalyzer *analyzer, const mission::RouteModel *model,
                   terrain::ElevationService *ground, QString customFile, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_analyzer(analyzer)
    , m_route(model)
    , m_customFile(std::move(customFile))
    , m_rule(std::make_unique<AirspaceRule>(ground))
    , m_set(std::make_shared<const ZoneSet>())
{
    Q_ASSERT(settings && analyzer && model);
    m_model = std::make_unique<ZoneListModel>(this);
    m_editor = std::make_unique<ZoneEditor>(this);
    bool ok = false;
    const double remembered = m_settings->value(kBufferKey).toDouble(&ok);
    if (ok && remembered >= 0 && std::isfinite(remembered))
        m_buffer = remembered;
    m_rule->setBuffer(m_buffer);
    analyzer->addRule(m_rule.get());
    connect(analyzer, &mission::RouteAnalyzer::recomputed, this, &Airspace::readCrossings);
    // The open route's own fence (a .plan's geoFence) follows the route: opened, replaced, undone.
    connect(model, &QAbstractItemModel::modelReset, this, &Airspace::followRouteFence);
    connect(model, &mission::RouteModel::settingsChanged, this, &Airspace::followRouteFence);
    // The chosen geographical zone's authorisation and whether it is in force follow the route.
    connect(model, &mission::RouteModel::settingsChanged, this, &Airspace::selectedGeoZoneChanged);
    connect(this, &Airspace::selectedZoneChanged, this, &Airspace::selectedGeoZoneChanged);
    connect(this, &Airspace::crossingsChanged, this, &Airspace::selectedGeoZoneChanged);
    connect(model, &mission::RouteModel::countChanged, this, &Airspace::followRouteFence);

    loadCustom();
    QStringList problems = m_problems;
    for (const QString &path : m_settings->value(kFilesKey).toStringList()) {
        const mission::Result<ZoneFile> read = loadZoneFile(path);
        if (!read) {
            problems << read.error().toString();
            continue;
        }
        m_files.push_back({path, read->zones});
        for (const QString &p : read->problems)
            problems << QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), p);
    }
    m_fence = zonesOfFence(m_route->route().fence, QCoreApplication::translate("Airspace", "route fence"), ZoneSource::File, QCoreApplication::translate("Airspace", "the open route"));
    setProblems(problems);
    rebuild();
}

Airspace::~Airspace() = default;

Airspace::Group Airspace::groupOf(int row) const
{
    return row >= 0 && row < int(m_groups.size()) ? m_groups[size_t(row)] : Group::File;
}

QString Airspace::groupName(Group group)
{
    switch (group) {
    case Group::Custom: return QCoreApplication::translate("Airspace", "drawn");
    case Group::Server: return QCoreApplication::translate("Airspace", "server");
    case Group::File: return QCoreApplication::translate("Airspace", "file");
    case Group::RouteFence: return QCoreApplication::translate("Airspace", "route fence");
    }
    return {};
}

QString Airspace::problemOf(int row) const
{
    return row >= 0 && row < int(m_shapeProblems.size()) ? m_shapeProblems[size_t(row)] : QString();
}

bool Airspace::appliesToFlight(int row) const
{
    if (row < 0 || row >= count() || !zoneAt(row).geoZone)
        return true;
    ed::TimeWindow window = m_rule->lastWindow();
    if (!window.from.isValid() || !window.to.isValid())
        window.from = window.to = QDateTime::currentDateTimeUtc();  // no route checked: now
    return zoneAt(row).geoZone->appliesDuring(window);
}

GeoZoneDetails Airspace::selectedGeoZone() const
{
    if (m_selected < 0 || m_selected >= count() || !zoneAt(m_selected).geoZone)
        return {};
    const ed::GeoZone &g = *zoneAt(m_selected).geoZone;
    GeoZoneDetails d;
    d.valid = true;
    d.identifier = g.identifier;
    d.restriction = ed::restrictionWords(g.restriction);
    d.needsAuthorisation = g.restriction == ed::Restriction::ReqAuthorisation;
    d.authorisation = m_route->authorisationFor(g.identifier);
    d.inForce = appliesToFlight(m_selected);
    QStringList lines;
    if (!g.message.isEmpty())
        lines << g.message;
    QStringList reasons = g.reasons;
    if (!g.otherReasonInfo.trimmed().isEmpty())
        reasons << g.otherReasonInfo.trimmed();
    if (!reasons.isEmpty())
        lines << tr("Reason: %1").arg(reasons.join(QStringLiteral(", ")));
    lines << tr("When: %1").arg(ed::applicabilityText(g.applicability, QTimeZone::systemTimeZone()));
    if (!d.inForce)
        lines << tr("Not in force during the planned flight.");
    for (const ed::Authority &a : g.authorities)
        lines << tr("Authority: %1").arg(ed::contactText(a));
    d.text = lines.join(QLatin1Char('\n'));
    return d;
}

bool Airspace::hasGeographicalZones() const
{
    const auto &zones = m_set->zones();
    return std::any_of(zones.begin(), zones.end(), [](const Zone &z) { return z.geoZone != nullptr; });
}

void Airspace::setBuffer(double metres)
{
    if (!(metres >= 0) || !std::isfinite(metres) || metres == m_buffer)
        return;
    m_buffer = metres;
    m_settings->setValue(kBufferKey, metres);
    m_rule->setBuffer(metres);
    emit bufferChanged();
}

QStringList Airspace::files() const
{
    QStringList out;
    for (const LoadedFile &f : m_files)
        out << f.path;
    return out;
}

void Airspace::setSelectedZone(int row)
{
    if (row < -1 || row >= count())
        row = -1;
    const Group group = groupOf(row);
    m_selectedKey = row < 0 || group == Group::Custom ? QString() : keyOf(group, zoneAt(row));
    if (row == m_selected)
        return;
    m_selected = row;
    emit selectedZoneChanged();
}

// After a rebuild the chosen zone keeps being chosen where its row went (server zones come and go
// above the files); a drawn zone's row is its index, which the edits keep up to date.
void Airspace::followSelection()
{
    int row = m_selected;
    if (!m_selectedKey.isEmpty()) {
        row = -1;
        for (int r = 0; r < count() && row < 0; ++r)
            if (m_groups[size_t(r)] != Group::Custom && keyOf(m_groups[size_t(r)], zoneAt(r)) == m_selectedKey)
                row = r;
    } else if (row >= int(m_custom.size())) {
        row = -1;
    }
    if (row == m_selected)
        return;
    m_selected = row;
    if (row < 0)
        m_selectedKey.clear();
    emit selectedZoneChanged();
}

int Airspace::draftOf(int serverId) const
{
    for (size_t i = 0; i < m_custom.size(); ++i)
        if (m_custom[i].serverId == serverId)
            return int(i);
    return -1;
}

int Airspace::rowOfServerZone(int serverId) const
{
    for (int r = 0; r < count(); ++r)
        if (m_groups[size_t(r)] == Group::Server && zoneAt(r).serverId == serverId)
            return r;
    return -1;
}

bool Airspace::loadFile(const QString &path)
{
    const mission::Result<ZoneFile> read = loadZoneFile(path);
    if (!read) {
        setProblems({read.error().toString()});
        qCWarning(lcAirspace).noquote() << "zone file not read:" << read.error().toString();
        return false;
    }
    const auto same = std::find_if(m_files.begin(), m_files.end(), [&](const LoadedFile &f) { return f.path == path; });
    if (same != m_files.end())
        same->zones = read->zones;
    else
        m_files.push_back({path, read->zones});
    qCInfo(lcAirspace).noquote() << read->zones.size() << "zones from" << path << "," << read->problems.size() << "left out";
    QStringList problems;
    for (const QString &p : read->problems)
        problems << QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), p);
    setProblems(problems);
    rememberFiles();
    rebuild();
    return true;
}

bool Airspace::loadFeedCopy(const QString &copy, const QUrl &url, const QDateTime &fetchedAtUtc)
{
    QVariantMap feeds = m_settings->value(kFeedsKey).toMap();
    feeds.insert(copy, QStringLiteral("%1 %2").arg(fetchedAtUtc.toUTC().toString(Qt::ISODate), url.toString(QUrl::FullyEncoded)));
    m_settings->setValue(kFeedsKey, feeds);
    return loadFile(copy);
}

QString Airspace::dataAge() const
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    QStringList lines;
    for (const LoadedFile &f : m_files) {
        const QString name = QFileInfo(f.path).fileName();
        if (const std::optional<FeedRecord> feed = feedRecordOf(*m_settings, f.path)) {
            lines << tr("%1: fetched from %2 %3").arg(name, feed->url.host(), daysAgo(feed->fetched, now));
        } else {
            const QDateTime changed = QFileInfo(f.path).lastModified().toUTC();
            lines << (changed.isValid() ? tr("%1: a file changed %2").arg(name, daysAgo(changed, now)) : name);
        }
    }
    if (dataStale())
        lines << tr("Some zone data is older than a week: fetch it or load it again before you fly.");
    return lines.join(QLatin1Char('\n'));
}

bool Airspace::dataStale() const
{
    const QDateTime weekAgo = QDateTime::currentDateTimeUtc().addDays(-kStaleDays);
    return std::any_of(m_files.begin(), m_files.end(), [&](const LoadedFile &f) {
        const std::optional<FeedRecord> feed = feedRecordOf(*m_settings, f.path);
        const QDateTime at = feed ? feed->fetched : QFileInfo(f.path).lastModified().toUTC();
        return at.isValid() && at < weekAgo;
    });
}

QList<QUrl> Airspace::feedUrls() const
{
    QList<QUrl> urls;
    for (const LoadedFile &f : m_files)
        if (const std::optional<FeedRecord> feed = feedRecordOf(*m_settings, f.path))
            urls << feed->url;
    return urls;
}

void Airspace::removeFile(const QString &path)
{
    const auto before = m_files.size();
    m_files.erase(std::remove_if(m_files.begin(), m_files.end(), [&](const LoadedFile &f) { return f.path == path; }), m_files.end());
    if (m_files.size() == before)
        return;
    QVariantMap feeds = m_settings->value(kFeedsKey).toMap();
    if (feeds.remove(path))
        m_settings->setValue(kFeedsKey, feeds);
    rememberFiles();
    rebuild();
}

void Airspace::setActive(int row, bool active)
{
    if (row < 0 || row >= count() || zoneAt(row).active == active)
        return;
    const Group group = groupOf(row);
    if (group == Group::Custom) {
        m_custom[size_t(row)].active = active;
        saveCustom();
    } else if (active) {
        m_inactive.remove(keyOf(group, zoneAt(row)));
    } else {
        m_inactive.insert(keyOf(group, zoneAt(row)));
    }
    rebuild();
}

bool Airspace::selectZoneOfIssue(const QString &message)
{
    const std::shared_ptr<const ZoneSet> &zones = m_rule->lastZones();
    if (!zones || zones != m_set)
        return false;
    const AirspaceReport &report = m_rule->lastReport();
    for (const AirspaceViolation &v : report.violations)
        if (violationMessage(v, zones->zones()[size_t(v.zone)], m_rule->lastAuthorisations()) == message) {
            setSelectedZone(v.zone);
            return true;
        }
    for (const AirspaceWarning &w : report.warnings)
        if (warningMessage(w, zones->zones()[size_t(w.zone)], m_buffer) == message) {
            setSelectedZone(w.zone);
            return true;
        }
    return false;
}

void Airspace::lookAt(double south, double west, double north, double east)
{
    if (!(south < north) || !(west < east) || !std::isfinite(south + west + north + east))
        return;
    if (!m_area.empty && south >= m_area.south && north <= m_area.north && west >= m_area.west && east <= m_area.east)
        return;
    const double dLat = (north - south) / 2, dLon = (east - west) / 2;
    m_area = {std::max(-90.0, south - dLat), std::max(-180.0, west - dLon), std::min(90.0, north + dLat), std::min(180.0, east + dLon), false};
    emit areaChanged();
}

void Airspace::setServerZones(std::vector<Zone> zones)
{
    m_server = std::move(zones);
    m_serverProblems.clear();
    for (const Zone &z : m_server)
        m_serverProblems.push_back(shapeProblem(z));
    rebuild();
}

void Airspace::insertCustomZone(int index, Zone zone)
{
    index = std::clamp(index, 0, int(m_custom.size()));
    m_custom.insert(m_custom.begin() + index, std::move(zone));
    saveCustom();
    rebuild();
    setSelectedZone(index);
}

void Airspace::removeCustomZone(int index)
{
    if (index < 0 || index >= int(m_custom.size()))
        return;
    m_custom.erase(m_custom.begin() + index);
    if (m_selectedKey.isEmpty() && m_selected >= index) {  // a drawn zone is chosen: its row moves up
        m_selected = m_selected == index ? -1 : m_selected - 1;
        emit selectedZoneChanged();
    }
    saveCustom();
    rebuild();
}

void Airspace::replaceCustomZone(int index, Zone zone)
{
    if (index < 0 || index >= int(m_custom.size()) || m_custom[size_t(index)] == zone)
        return;
    m_custom[size_t(index)] = std::move(zone);
    saveCustom();
    rebuild();
}

QString Airspace::keyOf(Group group, const Zone &zone) const
{
    // Not groupName (translated): a switched-off zone stays off when the language changes.
    return QString::number(int(group)) + QLatin1Char('\n') + zone.origin + QLatin1Char('\n') + zone.name;
}

void Airspace::followRouteFence()
{
    std::vector<Zone> fence = zonesOfFence(m_route->route().fence, QCoreApplication::translate("Airspace", "route fence"), ZoneSource::File,
                                           QCoreApplication::translate("Airspace", "the open route"));
    if (fence == m_fence)
        return;
    m_fence = std::move(fence);
    rebuild();
}

// One set per change: every source in row order, the operator's switches applied, a polygon that
// cannot be checked kept (drawn, listed with its reason) but not checked. Validity is checked here
// only for the drawn zones and the route's fence (a few); the server's were checked as they came,
// and the file readers leave such a polygon out.
void Airspace::rebuild()
{
    std::vector<Zone> all;
    std::vector<Group> groups;
    std::vector<QString> problems;
    const auto add = [&](const std::vector<Zone> &zones, Group group, const std::vector<QString> *known) {
        for (size_t i = 0; i < zones.size(); ++i) {
            Zone z = zones[i];
            if (group != Group::Custom && m_inactive.contains(keyOf(group, z)))
                z.active = false;
            QString problem = known ? (i < known->size() ? (*known)[i] : QString()) : shapeProblem(z);
            if (!problem.isEmpty())
                z.active = false;
            problems.push_back(std::move(problem));
            all.push_back(std::move(z));
            groups.push_back(group);
        }
    };
    static const std::vector<QString> none;
    add(m_custom, Group::Custom, nullptr);
    // A server zone the operator is editing here is drawn once: as the draft (ZoneSharing).
    std::vector<Zone> server;
    std::vector<QString> serverProblems;
    for (size_t i = 0; i < m_server.size(); ++i)
        if (!m_server[i].serverId || draftOf(*m_server[i].serverId) < 0) {
            server.push_back(m_server[i]);
            serverProblems.push_back(i < m_serverProblems.size() ? m_serverProblems[i] : QString());
        }
    add(server, Group::Server, &serverProblems);
    for (const LoadedFile &f : m_files)
        add(f.zones, Group::File, &none);
    add(m_fence, Group::RouteFence, nullptr);
    m_shapeProblems = std::move(problems);
    m_groups = std::move(groups);
    const int before = count();
    m_set = std::make_shared<const ZoneSet>(std::move(all));
    m_model->rebuilt(before);
    followSelection();
    m_rule->setZones(m_set);
    emit changed();
}

void Airspace::readCrossings()
{
    std::vector<ZoneCrossing> list;
    const std::shared_ptr<const ZoneSet> &zones = m_rule->lastZones();
    if (zones) {
        for (const AirspaceViolation &v : m_rule->lastReport().violations) {
            const Zone &z = zones->zones()[size_t(v.zone)];
            list.push_back({v.fromDistance, v.toDistance, v.leg, v.zone, z.name, z.kind, z.floor, z.ceiling,
                            stretchOf(m_rule->lastPath(), v.leg, v.fromDistance, v.toDistance),
                            z.geoZone ? std::optional<ed::Restriction>(z.geoZone->restriction) : std::nullopt});
        }
    }
    if (list == m_crossings)
        return;
    m_crossings = std::move(list);
    emit crossingsChanged();
}

void Airspace::rememberFiles()
{
    m_settings->setValue(kFilesKey, files());
}

void Airspace::saveCustom() const
{
    if (m_customFile.isEmpty())
        return;
    QString error;
    if (!writeCustomZones(m_customFile, m_custom, &error))
        qCWarning(lcAirspace).noquote() << "drawn zones not kept:" << error;
}

void Airspace::loadCustom()
{
    if (m_customFile.isEmpty() || !QFile::exists(m_customFile))
        return;
    const mission::Result<ZoneFile> read = readCustomZones(m_customFile);
    if (!read) {
        // Kept aside, never overwritten by the next save: the operator's zones may still be in it.
        const QString aside = m_customFile + QStringLiteral(".unreadable-") + QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMddHHmmss"));
        QFile::rename(m_customFile, aside);
        m_problems << QCoreApplication::translate("Airspace", "%1 (kept as %2)").arg(read.error().toString(), aside);
        qCWarning(lcAirspace).noquote() << "drawn zones not read:" << read.error().toString() << "; kept as" << aside;
        return;
    }
    m_custom = read->zones;
    m_problems << read->problems;
}

void Airspace::setProblems(QStringList problems)
{
    if (problems == m_problems)
        return;
    m_problems = std::move(problems);
    emit problemsChanged();
}

} // namespace sortie::airspace
