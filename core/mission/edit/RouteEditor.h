#pragma once

#include "Route.h"

#include <QItemSelectionModel>
#include <QList>
#include <QObject>
#include <QUndoStack>
#include <QVariantList>
#include <QVariantMap>

#include <functional>
#include <optional>

namespace sortie::mission {

class RouteModel;

// Every edit of a route as one undoable step, for QML (Q_INVOKABLE, rows as lists of ints: the
// view's selection) and C++ alike. Holds no state of its own besides the model and the stack.
class RouteEditor : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QUndoStack *undoStack READ undoStack CONSTANT)

public:
    RouteEditor(RouteModel *model, QUndoStack *stack, QObject *parent = nullptr);

    QUndoStack *undoStack() const { return m_stack; }
    RouteModel *model() const { return m_model; }

    // A new waypoint takes its altitude, type, speed and turn from the one before it (or from the
    // route's settings). Returns the new row.
    Q_INVOKABLE int addWaypoint(double latitude, double longitude);
    Q_INVOKABLE int insertWaypoint(int row, double latitude, double longitude);
    // Moves within one gesture (a drag) merge into one undo step; endMove() closes the gesture.
    Q_INVOKABLE void moveWaypoint(int row, double latitude, double longitude);
    Q_INVOKABLE void endMove() { ++m_gesture; }
    Q_INVOKABLE void removeRows(const QList<int> &rows);
    Q_INVOKABLE void moveRows(const QList<int> &rows, int destination);
    // Reverses the span from the first to the last selected row; the whole route when empty.
    Q_INVOKABLE void reverse(const QList<int> &rows = {});

    // Bulk edits of a selection; each is one undo step. Rows that an edit does not apply to
    // (turn type on an area scan) are left alone.
    Q_INVOKABLE void setAltitude(const QList<int> &rows, double altitude);
    // With keepHeight (and a ground lookup), a waypoint keeps the height it flies at: AGL -> AMSL adds
    // the ground under it, AMSL -> AGL subtracts it. Without terrain there, the number stays.
    Q_INVOKABLE bool setAltitudeType(const QList<int> &rows, const QString &type, bool keepHeight = true);
    Q_INVOKABLE void setSpeed(const QList<int> &rows, double speed);
    Q_INVOKABLE bool setTurnType(const QList<int> &rows, const QString &type);
    Q_INVOKABLE void setAcceptanceRadius(const QList<int> &rows, double meters);
    Q_INVOKABLE bool addAction(const QList<int> &rows, const QVariantMap &action);
    Q_INVOKABLE void removeAction(const QList<int> &rows, int actionIndex);
    // Replaces the action at actionIndex (in every selected waypoint that has one there).
    Q_INVOKABLE bool setAction(const QList<int> &rows, int actionIndex, const QVariantMap &action);
    Q_INVOKABLE void clearActions(const QList<int> &rows);
    // polygon: list of {latitude, longitude}. Returns the new row, or -1 for a bad polygon.
    Q_INVOKABLE int addAreaScan(const QVariantList &polygon);
    // Changes the keys given (see ScanVariants.h); false for a bad value or a row that is no scan.
    Q_INVOKABLE bool setScanProperties(int row, const QVariantMap &parameters);
    Q_INVOKABLE bool setRouteProperty(const QString &name, const QVariant &value);
    // The rows a view's selection covers, sorted, for the bulk edits above.
    Q_INVOKABLE QList<int> rowsOf(const QItemSelectionModel *selection) const;

    // C++ side of the same operations.
    int insertSegments(int row, std::vector<Segment> segments, const QString &text);
    void editSegments(const QList<int> &rows, const std::function<void(Segment &)> &edit, const QString &text);
    void setSettings(const RouteSettings &settings, const QString &text);
    void replaceRoute(Route route, const QString &text);
    void setScanParameters(int row, const AreaScanParameters &parameters);
    void setScanPolygon(int row, std::vector<GeoPoint> polygon);

    Waypoint newWaypointAt(int row, const GeoPoint &position) const;

    // The ground elevation (metres above the geoid) at a point, nullopt where unknown: set by the
    // application from its terrain sources, used by setAltitudeType.
    using GroundLookup = std::function<std::optional<double>(const GeoPoint &)>;
    void setGroundLookup(GroundLookup lookup) { m_ground = std::move(lookup); }

private:
    std::vector<int> validRows(const QList<int> &rows) const;

    RouteModel *m_model;
    QUndoStack *m_stack;
    GroundLookup m_ground;
    int m_gesture = 0;
};

} // namespace sortie::mission
