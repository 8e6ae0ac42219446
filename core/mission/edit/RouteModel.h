#pragma once

#include "Route.h"
#include "ScanPlanCache.h"

#include <QAbstractListModel>

#include <vector>

namespace sortie::mission {

// The route being edited, one row per segment (waypoint or area scan), as plain values: no QObject
// per waypoint, so 10,000+ rows stay cheap. Views read it through roles; edits go through
// RouteEditor, the one entry point: the model itself is read-only to views.
// The mutators below are the primitives the undo commands use; they are not undoable themselves.
class RouteModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)
    Q_PROPERTY(QString name READ name NOTIFY settingsChanged)
    Q_PROPERTY(double safeAltitude READ safeAltitude NOTIFY settingsChanged)
    Q_PROPERTY(double maxAltitude READ maxAltitude NOTIFY settingsChanged)
    Q_PROPERTY(double initialSpeed READ initialSpeed NOTIFY settingsChanged)
    Q_PROPERTY(double maxSpeed READ maxSpeed NOTIFY settingsChanged)
    // Does the server's processing refuse a route crossing an aerodrome's / a custom no-fly zone?
    Q_PROPERTY(bool checkAerodromeNfz READ checkAerodromeNfz NOTIFY settingsChanged)
    Q_PROPERTY(bool checkCustomNfz READ checkCustomNfz NOTIFY settingsChanged)
    // The flight's planned start (UTC); invalid when none is planned (the flight starts now).
    Q_PROPERTY(QDateTime plannedStart READ plannedStart NOTIFY settingsChanged)
    // The planned start in the operator's time zone as RouteEditor::setPlannedStartText reads it;
    // empty when none is planned (the flight is checked as starting now).
    Q_PROPERTY(QString plannedStartText READ plannedStartText NOTIFY settingsChanged)
    // The geographical zones the operator recorded an authorisation for (authorisationFor gives it).
    Q_PROPERTY(QStringList authorisedZones READ authorisedZones NOTIFY settingsChanged)

public:
    enum Roles {
        KindRole = Qt::UserRole + 1,  // "waypoint", "takeoff", "land", "areaScan", "circle", ... "unknown"
        SequenceRole,                 // 1-based row number
        LatitudeRole,                 // degrees (a scan: its first vertex)
        LongitudeRole,
        AltitudeRole,                 // metres (a scan: its flight altitude)
        AltitudeTypeRole,             // "AGL" / "AMSL"
        SpeedRole,                    // m/s
        TurnTypeRole,                 // "StopAndTurn", "Straight", "Spline", "BankTurn"
        AcceptanceRadiusRole,         // metres, 0 = vehicle default
        ActionCountRole,
        ActionsSummaryRole,           // "Wait 5 s · Photo every 20 m"
        ActionsRole,                  // list of maps, see ActionVariants.h
        ActionMarksRole,              // what a map marks: ActionMark flags (camera, other), 0 for none
        PolygonRole,                  // an area's corners, a corridor's line, a circle's centre: list of {latitude, longitude}
        ScanParametersRole,           // a segment's parameters by wire name (SegmentParameters.h); none for a waypoint
        LabelRole,                    // "Waypoint 3", "Circle 5"
    };
    Q_ENUM(Roles)
    enum ActionMark { CameraMark = 1, OtherActionMark = 2 };

    explicit RouteModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

    const Route &route() const { return m_route; }
    const RouteSettings &settings() const { return m_route.settings; }
    const Segment &segment(int row) const { return m_route.segments[size_t(row)]; }
    int count() const { return int(m_route.segments.size()); }
    QString name() const { return m_route.settings.name; }
    double safeAltitude() const { return m_route.settings.safeAltitude; }
    double maxAltitude() const { return m_route.settings.maxAltitude; }
    double initialSpeed() const { return m_route.settings.initialSpeed; }
    double maxSpeed() const { return m_route.settings.maxSpeed; }
    bool checkAerodromeNfz() const { return m_route.settings.checkAerodromeNfz; }
    bool checkCustomNfz() const { return m_route.settings.checkCustomNfz; }
    QDateTime plannedStart() const { return m_route.settings.plannedStart.value_or(QDateTime()); }
    QString plannedStartText() const;
    QStringList authorisedZones() const;
    Q_INVOKABLE QString authorisationFor(const QString &identifier) const;

    // Primitives for the undo commands. Rows are sorted ascending and valid.
    void insertSegments(int row, std::vector<Segment> segments);
    std::vector<Segment> takeSegments(const std::vector<int> &rows);
    void restoreSegments(const std::vector<int> &rows, std::vector<Segment> segments);  // inverse of takeSegments
    void replaceSegments(const std::vector<int> &rows, const std::vector<Segment> &values);
    void permute(const std::vector<int> &order);  // new row i holds old row order[i]
    void setSettings(const RouteSettings &settings);
    void resetRoute(Route route);

    // An area scan's or photogrammetry's plan (or why it has none), from the cache the map's layer
    // fills too; none for a segment that is no scan.
    std::optional<AreaScanOutcome> scanPlan(int row) const;

    static QString segmentLabelFor(int row, const Segment &s);  // "Waypoint 12", "Area scan 4", "Circle 5"

signals:
    void countChanged();
    void settingsChanged();
    // After every change of content, whatever its kind: what analyzers listen to.
    void routeEdited();

private:
    void emitChanged(const std::vector<int> &rows, const QList<int> &roles);

    Route m_route;
    mutable ScanPlanCache m_scanPlans;  // plans given by scanPlan()
};

// Contiguous runs [first, last] of sorted rows.
std::vector<std::pair<int, int>> contiguousRuns(const std::vector<int> &sortedRows);

} // namespace sortie::mission
