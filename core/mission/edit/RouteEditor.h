#pragma once

#include "AlgorithmCatalog.h"
#include "DrawingTools.h"
#include "MissionEnums.h"
#include "Route.h"

#include <QGeoCoordinate>
#include <QItemSelectionModel>
#include <QList>
#include <QObject>
#include <QStringList>
#include <QUndoStack>
#include <QVariantMap>

#include <functional>
#include <optional>

namespace sortie::mission {

class RouteModel;

// The one way to edit a route. QML (map gestures, table cells, the bulk bar, the segment
// editor) and C++ (tests, imports, conflicts, autosave recovery) all call these; each call is one
// undo step. Arguments are typed: positions are QGeoCoordinates, choices are MissionEnums,
// segment parameters go by their UgCS wire names through the one parameter reader
// (SegmentParameters.h).
//
// Undo merging has one mechanism: a continuous gesture (a drag of a handle, a dial) sends its
// steps with EditStep::Continuing and its last one with EditStep::Done. Steps of one gesture that
// edit the same rows the same way merge into one undo step; Done closes the gesture.
//
// An edit that cannot apply (a bad value, a row out of range, a polygon without area) returns
// false (or -1 for a row) and reports why with refused().
class RouteEditor : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QUndoStack *undoStack READ undoStack CONSTANT)
    Q_PROPERTY(QStringList drawingToolNames READ drawingToolNames NOTIFY catalogChanged)

public:
    RouteEditor(RouteModel *model, QUndoStack *stack, QObject *parent = nullptr);

    QUndoStack *undoStack() const { return m_stack; }
    RouteModel *model() const { return m_model; }

    // A new waypoint takes its altitude, type, speed and turn from the one before it (or from the
    // route's settings). Returns the new row, or -1.
    Q_INVOKABLE int addWaypoint(const QGeoCoordinate &at);
    Q_INVOKABLE int insertWaypoint(int row, const QGeoCoordinate &at);
    // Moves rows to positions (in the same order): a waypoint goes there, any other segment moves
    // whole by its anchor, its figure keeping its shape (a marker dragged on the map).
    Q_INVOKABLE bool moveWaypoints(const QList<int> &rows, const QList<QGeoCoordinate> &to,
                                   sortie::mission::MissionEnums::EditStep step = EditStep::Done);
    // One axis of one waypoint, as a table cell types it.
    Q_INVOKABLE bool setLatitude(int row, double latitude);
    Q_INVOKABLE bool setLongitude(int row, double longitude);
    Q_INVOKABLE void removeRows(const QList<int> &rows);
    Q_INVOKABLE void moveRows(const QList<int> &rows, int destination);
    // Reverses the span from the first to the last selected row; the whole route when empty.
    Q_INVOKABLE void reverse(const QList<int> &rows = {});

    // Edits of a selection, each one undo step. Rows an edit does not apply to (turn type on an
    // area scan) are left alone.
    Q_INVOKABLE bool setAltitude(const QList<int> &rows, double altitude,
                                 sortie::mission::MissionEnums::EditStep step = EditStep::Done);
    // With keepHeight (and a ground lookup), a waypoint keeps the height it flies at: AGL -> AMSL adds
    // the ground under it, AMSL -> AGL subtracts it. Without terrain there, the number stays.
    Q_INVOKABLE bool setAltitudeType(const QList<int> &rows, sortie::mission::MissionEnums::AltitudeType type, bool keepHeight = true);
    // The altitude as a height of `frame` (AMSL or AGL) whatever type each row keeps it in: a waypoint
    // of the other type gets it converted through the ground under it, and is refused (nothing
    // changes) where the ground is unknown. A segment's height is one number over varying ground, so
    // it is set only in its own type.
    Q_INVOKABLE bool setAltitudeIn(const QList<int> &rows, double altitude, sortie::mission::MissionEnums::AltitudeType frame);
    Q_INVOKABLE bool setSpeed(const QList<int> &rows, double speed);
    Q_INVOKABLE bool setTurnType(const QList<int> &rows, sortie::mission::MissionEnums::TurnType type);
    Q_INVOKABLE bool setAcceptanceRadius(const QList<int> &rows, double meters);
    // Actions as maps (see ActionVariants.h).
    Q_INVOKABLE bool addAction(const QList<int> &rows, const QVariantMap &action);
    Q_INVOKABLE void removeAction(const QList<int> &rows, int actionIndex);
    // Replaces the action at actionIndex (in every selected waypoint that has one there).
    Q_INVOKABLE bool setAction(const QList<int> &rows, int actionIndex, const QVariantMap &action);
    Q_INVOKABLE void clearActions(const QList<int> &rows);

    // One parameter of every selected segment that has it, by its wire name (SegmentParameters.h),
    // typed: a number, a bool, a selection name or enum.
    Q_INVOKABLE bool setParameter(const QList<int> &rows, const QString &name, const QVariant &value,
                                  sortie::mission::MissionEnums::EditStep step = EditStep::Done);

    // Area scans: a polygon of at least three corners enclosing an area. Returns the new row or -1.
    Q_INVOKABLE int addAreaScan(const QList<QGeoCoordinate> &polygon);
    // A segment of any algorithm by class name (full or short: "CircleAlgorithm") on the points
    // drawn: a polygon's corners, a corridor's centre line, a circle's centre, a point. Its
    // parameters start at the definition's defaults, its height and speed at the route's.
    // Returns the new row or -1.
    Q_INVOKABLE int addSegment(const QString &algorithm, const QList<QGeoCoordinate> &points);
    // The tools an operator draws on the map, from the catalog (DrawingTools.h), area scan first:
    // their names for a picker, and one by its index there (an invalid tool past the end).
    QStringList drawingToolNames() const;
    Q_INVOKABLE sortie::mission::DrawingTool drawingTool(int index) const;
    // The figure's points (area corners, corridor line, circle centre) by index.
    Q_INVOKABLE bool moveVertex(int row, int vertex, const QGeoCoordinate &to,
                                sortie::mission::MissionEnums::EditStep step = EditStep::Done);
    // A point between `vertex - 1` and `vertex` (a click on that edge); vertex == count appends.
    Q_INVOKABLE bool insertVertex(int row, int vertex, const QGeoCoordinate &at);
    // Keeps the points the figure needs (three corners, two line points).
    Q_INVOKABLE bool removeVertex(int row, int vertex);
    // A circle's radius in metres (its figure parameter).
    Q_INVOKABLE bool setRadius(int row, double meters, sortie::mission::MissionEnums::EditStep step = EditStep::Done);

    // The algorithms a server described (TraverseAlgorithm); the built-in ones until then.
    void setCatalog(const AlgorithmCatalog *catalog);
    const AlgorithmCatalog &catalog() const;

    Q_INVOKABLE bool setRouteProperty(const QString &name, const QVariant &value);
    // Whether the server's route processing checks the route against aerodrome / custom no-fly
    // zones (one undo step each; setting the value it has does nothing).
    Q_INVOKABLE void setCheckAerodromeNfz(bool check);
    Q_INVOKABLE void setCheckCustomNfz(bool check);
    // When the flight is planned to start (kept in UTC); an invalid time clears it: the flight is
    // checked as starting now. One undo step.
    Q_INVOKABLE void setPlannedStart(const QDateTime &start);
    // The planned start as the operator types it, in their own time zone: "2026-12-05 18:00"
    // (kPlannedStartFormat); empty text clears it. Anything else is refused (false, refused()).
    Q_INVOKABLE bool setPlannedStartText(const QString &localText);
    static constexpr const char *kPlannedStartFormat = "yyyy-MM-dd HH:mm";
    // Records the reference an authority gave for the geographical zone `identifier`; an empty
    // reference removes the authorisation. One undo step; false (refused) without an identifier.
    Q_INVOKABLE bool recordAuthorisation(const QString &identifier, const QString &reference);
    // The rows a view's selection covers, sorted.
    Q_INVOKABLE QList<int> rowsOf(const QItemSelectionModel *selection) const;

    // C++ only: whole segments, settings and routes.
    int insertSegments(int row, std::vector<Segment> segments, const QString &text);
    void setSettings(const RouteSettings &settings, const QString &text);
    void replaceRoute(Route route, const QString &text);
    Waypoint newWaypointAt(int row, const GeoPoint &position) const;

    // The ground elevation (metres above the geoid) at a point, nullopt where unknown: set by the
    // application from its terrain sources, used by setAltitudeType and setAltitudeIn.
    using GroundLookup = std::function<std::optional<double>(const GeoPoint &)>;
    void setGroundLookup(GroundLookup lookup) { m_ground = std::move(lookup); }
    bool hasGroundLookup() const { return bool(m_ground); }

signals:
    // Rows an edit added (addWaypoint, insertWaypoint, addAreaScan): views select them.
    void rowsAdded(int first, int count);
    // Another description of the algorithms arrived: editors rebuild.
    void catalogChanged();
    void refused(const QString &reason);

private:
    std::vector<int> validRows(const QList<int> &rows) const;
    // Pushes one in-place edit of `rows`; `kind` names what it does, for merging gestures.
    // change(row, segment) returns false (after refuse()) to cancel the whole edit.
    bool edit(const QList<int> &rows, const std::function<bool(int, Segment &)> &change, const QString &text,
              const QString &kind, EditStep step);
    bool refuse(const QString &reason);
    // A segment's altitude in its own type: a waypoint's, a point figure's, else its "height".
    bool applyAltitude(Segment &s, double altitude);

    RouteModel *m_model;
    QUndoStack *m_stack;
    const AlgorithmCatalog *m_catalog = nullptr;
    GroundLookup m_ground;
    int m_gesture = 1;          // the gesture steps belong to; Done closes it
    bool m_gestureOpen = false;  // a Continuing step of m_gesture was pushed
};

} // namespace sortie::mission
