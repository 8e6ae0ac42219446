#pragma once

#include "MissionEnums.h"
#include "Zone.h"

#include <QGeoCoordinate>
#include <QObject>
#include <QUndoStack>
#include <QVariant>

#include <functional>

namespace sortie::airspace {

class Airspace;

// The chosen drawn zone's fields as the zone panel shows and edits them; `chosen` is false (and the
// rest empty) when no drawn zone is chosen. Heights are the metres as the operator would type them,
// empty for "from the ground" and "unlimited": a missing limit is never shown as 0.
struct ZoneFields
{
    Q_GADGET
    Q_PROPERTY(bool chosen MEMBER chosen)
    Q_PROPERTY(QString name MEMBER name)
    Q_PROPERTY(bool inclusion MEMBER inclusion)
    Q_PROPERTY(QString floor MEMBER floor)
    Q_PROPERTY(QString ceiling MEMBER ceiling)
    Q_PROPERTY(QString reference MEMBER reference)  // "AMSL", "AGL", "HOME"

public:
    bool chosen = false;
    QString name;
    bool inclusion = false;
    QString floor, ceiling;
    QString reference = QStringLiteral("AMSL");
    bool operator==(const ZoneFields &) const = default;
};

// The one way to edit the zones the operator draws (the store's drawn zones, by their index there,
// which is also their row: they come first). Each call is one undo step on this editor's own
// stack: a zone is not part of the route, so editing one neither marks the route changed nor
// reaches its autosave. Gestures merge as the route editor's do: a drag sends
// EditStep::Continuing while it lasts and Done at the drop, and becomes one step.
//
// A polygon is its outer ring; a circle's vertex 0 is its centre. An edit that cannot apply (fewer
// than three corners, a ring that crosses itself, a ceiling under the floor) changes nothing,
// returns false and says why with refused().
class ZoneEditor : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QUndoStack *undoStack READ undoStack CONSTANT)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY stackChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY stackChanged)
    // The chosen drawn zone as the map edits it: its corners (QGeoCoordinates; a circle: its
    // centre), its radius in metres (0 for a polygon), and its fields; empty when no drawn zone is chosen.
    Q_PROPERTY(QVariantList figure READ figure NOTIFY figureChanged)
    Q_PROPERTY(double radius READ radius NOTIFY figureChanged)
    Q_PROPERTY(sortie::airspace::ZoneFields fields READ fields NOTIFY figureChanged)

public:
    explicit ZoneEditor(Airspace *store);

    QUndoStack *undoStack() { return &m_stack; }
    bool canUndo() const { return m_stack.canUndo(); }
    bool canRedo() const { return m_stack.canRedo(); }
    QVariantList figure() const;
    double radius() const;
    ZoneFields fields() const;

    // New zones: an exclusion zone from the ground up, unlimited, named "Zone N". Return its index or -1.
    Q_INVOKABLE int addPolygon(const QList<QGeoCoordinate> &corners);
    static constexpr double kDefaultRadius = 200.0;  // metres, a circle placed with one click
    Q_INVOKABLE int addCircle(const QGeoCoordinate &centre, double radius = kDefaultRadius);
    Q_INVOKABLE bool removeZone(int zone);
    // For ZoneSharing: a server zone's copy drawn here to be edited (one step, `text`), and a
    // drawn zone that went to the server taken off the drawn ones (one step: undo brings the draft back).
    int adopt(Zone zone, const QString &text) { return add(std::move(zone), text); }
    bool removeZoneAs(int zone, const QString &text);

    Q_INVOKABLE bool moveVertex(int zone, int vertex, const QGeoCoordinate &to,
                                sortie::mission::MissionEnums::EditStep step = sortie::mission::EditStep::Done);
    // A corner between `vertex - 1` and `vertex` (a click on that edge); vertex == count appends.
    Q_INVOKABLE bool insertVertex(int zone, int vertex, const QGeoCoordinate &at);
    Q_INVOKABLE bool removeVertex(int zone, int vertex);
    Q_INVOKABLE bool setRadius(int zone, double metres, sortie::mission::MissionEnums::EditStep step = sortie::mission::EditStep::Done);
    Q_INVOKABLE bool setName(int zone, const QString &name);
    Q_INVOKABLE bool setKind(int zone, const QString &kind);  // "exclusion" / "inclusion"
    // Floor and ceiling in metres, numbers or text as typed (null, undefined, empty text or NaN:
    // ground / unlimited; other text is refused), both in `reference` ("AMSL", "AGL", "HOME").
    Q_INVOKABLE bool setLimits(int zone, const QVariant &floor, const QVariant &ceiling, const QString &reference);

    Q_INVOKABLE void undo() { m_stack.undo(); }
    Q_INVOKABLE void redo() { m_stack.redo(); }

signals:
    void stackChanged();
    void figureChanged();
    void refused(const QString &reason);

private:
    bool edit(int zone, const std::function<bool(Zone &)> &change, const QString &text, const QString &kind,
              mission::EditStep step = mission::EditStep::Done);
    int add(Zone zone, const QString &text);
    bool refuse(const QString &reason);
    QString nextName() const;

    Airspace *m_store;
    QUndoStack m_stack;
    int m_gesture = 1;
    bool m_gestureOpen = false;
};

} // namespace sortie::airspace
