#pragma once

#include "Zone.h"

#include <QUndoCommand>

namespace sortie::airspace {

class Airspace;

// One undo step for an edit of one drawn zone (a corner moved, the radius, the name, the limits):
// redo and undo put the whole zone back. Steps of one gesture (same gesture number, not 0) doing
// the same kind of edit to the same zone merge, keeping the zone the gesture started from and the
// latest one, as the route editor's EditSegmentsCommand does.
class EditZoneCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x5a01;

    // gesture 0: never merges.
    EditZoneCommand(Airspace *store, int index, Zone before, Zone after, const QString &text, QString kind = {}, int gesture = 0);
    void redo() override;
    void undo() override;
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    Airspace *m_store;
    int m_index;
    Zone m_before;
    Zone m_after;
    QString m_kind;
    int m_gesture;
};

} // namespace sortie::airspace
