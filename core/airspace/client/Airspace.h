#pragma once

#include "AirspaceCheck.h"
#include "Zone.h"

#include <QObject>
#include <QSet>
#include <QStringList>
#include <QUrl>
#include <QVariant>

#include <memory>
#include <optional>
#include <vector>

class QSettings;

namespace sortie::mission {
class RouteAnalyzer;
class RouteModel;
} // namespace sortie::mission
namespace sortie::terrain {
class ElevationService;
}

namespace sortie::airspace {

class AirspaceRule;
class ZoneEditor;
class ZoneListModel;

// Where the open route is inside a zone it must not be in, as the last check found it: the map
// draws the stretch red (ZoneCrossingLayer), the terrain profile the zone's limits (ZoneProfileOverlay).
struct ZoneCrossing
{
    double from = 0, to = 0;  // metres along the flown path
    int leg = 0;
    int zone = -1;            // the zone's row
    QString name;
    ZoneKind kind = ZoneKind::Exclusion;
    std::optional<HeightLimit> floor, ceiling;  // none: the ground / unlimited
    std::vector<mission::GeoPoint> path;        // the stretch along the flown path, both ends included
    std::optional<ed::Restriction> restriction; // a geographical zone's; none for any other zone
    bool operator==(const ZoneCrossing &) const = default;
};

// The chosen zone's geographical zone (ED-269, ED-318) as the zone panel shows it: what it
// restricts, why, when, who to ask, and the authorisation the route holds for it. `valid` is false
// when the chosen zone is none.
struct GeoZoneDetails
{
    Q_GADGET
    Q_PROPERTY(bool valid MEMBER valid)
    Q_PROPERTY(QString identifier MEMBER identifier)
    Q_PROPERTY(QString restriction MEMBER restriction)      // in the operator's words
    Q_PROPERTY(bool needsAuthorisation MEMBER needsAuthorisation)
    Q_PROPERTY(QString authorisation MEMBER authorisation)  // the route's, empty when none is recorded
    Q_PROPERTY(bool inForce MEMBER inForce)                 // during the flight's window
    Q_PROPERTY(QString text MEMBER text)                    // message, reasons, when, authorities

public:
    bool valid = false;
    QString identifier, restriction;
    bool needsAuthorisation = false;
    QString authorisation;
    bool inForce = true;
    QString text;
    bool operator==(const GeoZoneDetails &) const = default;
};

// The client's one store of zones, by where they come from: zones the operator drew (custom,
// edited through `editor`), the server's (pushed in by setServerZones), zone files the operator
// loaded (.plan, .geojson/.json, .kml; remembered in the settings), and the open route's own .plan
// geofence. Rows are in that order; a row is also the zone's index in zoneSet(), so a violation's
// zone is a row. Each change rebuilds the set once and hands it to the airspace rule on the
// route's analyzer (so the issue list and the upload gate judge the same zones).
class Airspace : public QObject
{
    Q_OBJECT
    Q_MOC_INCLUDE("ZoneEditor.h")
    Q_MOC_INCLUDE("ZoneListModel.h")
    Q_PROPERTY(sortie::airspace::ZoneListModel *zones READ zones CONSTANT)
    Q_PROPERTY(sortie::airspace::ZoneEditor *editor READ editor CONSTANT)
    Q_PROPERTY(int count READ count NOTIFY changed)
    Q_PROPERTY(double buffer READ buffer WRITE setBuffer NOTIFY bufferChanged)  // metres; a warning within it
    Q_PROPERTY(QStringList files READ files NOTIFY changed)                    // the zone files loaded
    // What the last load left out or could not read, each line naming the file and the feature.
    Q_PROPERTY(QStringList problems READ problems NOTIFY problemsChanged)
    // The zone the operator chose (the list, an issue, the map), -1 for none.
    Q_PROPERTY(int selectedZone READ selectedZone WRITE setSelectedZone NOTIFY selectedZoneChanged)
    // The chosen zone when it is a custom one (its index in the editor's terms), else -1.
    Q_PROPERTY(int selectedCustom READ selectedCustom NOTIFY selectedZoneChanged)
    // How many stretches of the route cross zones, as the last check found (crossings() has them).
    Q_PROPERTY(int crossingCount READ crossingCount NOTIFY crossingsChanged)
    Q_PROPERTY(bool hasGeographicalZones READ hasGeographicalZones NOTIFY changed)
    // How old the zone data is, a line per file ("swiss.json: fetched from … 2 days ago"), and
    // whether any of it is older than a week (the zone panel then warns).
    Q_PROPERTY(QString dataAge READ dataAge NOTIFY changed)
    Q_PROPERTY(bool dataStale READ dataStale NOTIFY changed)
    Q_PROPERTY(QList<QUrl> feedUrls READ feedUrls NOTIFY changed)  // the feeds loaded, for fetching them again
    Q_PROPERTY(sortie::airspace::GeoZoneDetails selectedGeoZone READ selectedGeoZone NOTIFY selectedGeoZoneChanged)

public:
    enum class Group { Custom, Server, File, RouteFence };

    // `settings` (not owned) keeps the buffer and the files; `analyzer` and `model` are the open
    // route's; `ground` (may be null) gives AGL heights; `customFile` keeps the drawn zones across
    // restarts (empty: they live as long as the program).
    Airspace(QSettings *settings, mission::RouteAnalyzer *analyzer, const mission::RouteModel *model,
             terrain::ElevationService *ground, QString customFile = {}, QObject *parent = nullptr);
    ~Airspace() override;

    ZoneListModel *zones() const { return m_model.get(); }
    ZoneEditor *editor() const { return m_editor.get(); }
    AirspaceRule *rule() const { return m_rule.get(); }
    std::shared_ptr<const ZoneSet> zoneSet() const { return m_set; }

    int count() const { return int(m_set->zones().size()); }
    // The zone at a row as checked (with the operator's active switch applied).
    const Zone &zoneAt(int row) const { return m_set->zones()[size_t(row)]; }
    Group groupOf(int row) const;
    Q_INVOKABLE QString zoneName(int row) const { return row >= 0 && row < count() ? zoneAt(row).name : QString(); }
    static QString groupName(Group group);  // "drawn", "server", "file", "route fence"
    // Why a zone is not checked although active (a polygon that crosses itself); empty when it is.
    QString problemOf(int row) const;
    // Whether a zone applies to the flight as last checked: a geographical zone's schedule against
    // the flight's window (the route's planned start, or now, to its end); any other zone always.
    bool appliesToFlight(int row) const;
    // Whether any zone loaded is a geographical zone (ED-269, ED-318): the map then shows its legend.
    bool hasGeographicalZones() const;
    GeoZoneDetails selectedGeoZone() const;

    double buffer() const { return m_buffer; }
    void setBuffer(double metres);
    QStringList files() const;
    QStringList problems() const { return m_problems; }
    int selectedZone() const { return m_selected; }
    void setSelectedZone(int row);
    int selectedCustom() const { return m_selected >= 0 && m_selected < int(m_custom.size()) ? m_selected : -1; }
    // Where the route crosses zones, by leg and distance.
    const std::vector<ZoneCrossing> &crossings() const { return m_crossings; }
    int crossingCount() const { return int(m_crossings.size()); }

    // A zone file: read, its zones added (a file loaded again replaces its zones), remembered.
    // false when it cannot be read at all; features left out are listed in `problems` either way.
    Q_INVOKABLE bool loadFile(const QString &path);
    Q_INVOKABLE bool loadFileUrl(const QUrl &file) { return loadFile(file.toLocalFile()); }
    Q_INVOKABLE void removeFile(const QString &path);
    // A feed's copy as ZoneFeed kept it: loaded as a zone file, remembered with its URL and the time
    // it was fetched (what dataAge says of it, across restarts).
    bool loadFeedCopy(const QString &copy, const QUrl &url, const QDateTime &fetchedAtUtc);
    QString dataAge() const;
    bool dataStale() const;
    QList<QUrl> feedUrls() const;
    static constexpr int kStaleDays = 7;
    // The operator's switch: an inactive zone is kept and drawn, not checked.
    Q_INVOKABLE void setActive(int row, bool active);
    // Selects the zone an airspace issue names (its message as the rule wrote it); false when the
    // message is not one of the last check's.
    Q_INVOKABLE bool selectZoneOfIssue(const QString &message);

    // The server's zones (aerodromes and custom ones), replacing the ones it gave before.
    void setServerZones(std::vector<Zone> zones);
    // Where a map looks (degrees): the area whose server zones matter. The area asked for is the
    // view grown by half its size each way, so panning within it asks nothing new.
    Q_INVOKABLE void lookAt(double south, double west, double north, double east);
    const mission::GeoBox &area() const { return m_area; }

    // The drawn zone that is a copy of the server's zone `serverId` (edited here, to be sent back), or -1.
    int draftOf(int serverId) const;
    // The row of the server's zone `serverId` as listed (-1 when it is not, or while a draft hides it).
    int rowOfServerZone(int serverId) const;

    // The drawn zones: what ZoneEditor's commands change (each a whole zone, so undo restores it).
    const std::vector<Zone> &customZones() const { return m_custom; }
    void insertCustomZone(int index, Zone zone);
    void removeCustomZone(int index);
    void replaceCustomZone(int index, Zone zone);

signals:
    void changed();
    void bufferChanged();
    void problemsChanged();
    void selectedZoneChanged();
    void selectedGeoZoneChanged();  // another zone chosen, its authorisation recorded, the window moved
    void crossingsChanged();
    void areaChanged();

private:
    struct LoadedFile
    {
        QString path;
        std::vector<Zone> zones;
    };
    QString keyOf(Group group, const Zone &zone) const;
    void followRouteFence();
    void rebuild();
    void followSelection();
    void readCrossings();
    void rememberFiles();
    void saveCustom() const;
    void loadCustom();
    void setProblems(QStringList problems);

    QSettings *m_settings;
    mission::RouteAnalyzer *m_analyzer;
    const mission::RouteModel *m_route;
    QString m_customFile;
    std::unique_ptr<AirspaceRule> m_rule;
    std::unique_ptr<ZoneListModel> m_model;
    std::unique_ptr<ZoneEditor> m_editor;
    std::vector<Zone> m_custom, m_server, m_fence;
    mission::GeoBox m_area;
    std::vector<LoadedFile> m_files;
    std::vector<Group> m_groups;            // by row, as last built
    std::vector<QString> m_shapeProblems;   // by row
    std::vector<QString> m_serverProblems;  // by server zone, found as they came
    QSet<QString> m_inactive;               // keys of zones switched off (not custom: they carry it)
    std::shared_ptr<const ZoneSet> m_set;
    double m_buffer = 20.0;
    QStringList m_problems;
    int m_selected = -1;
    QString m_selectedKey;  // the chosen zone when it is not a drawn one (keyOf): rows move, it does not
    std::vector<ZoneCrossing> m_crossings;
};

} // namespace sortie::airspace
