#pragma once

#include "Segment.h"

#include <QUndoCommand>

#include <vector>

namespace sortie::mission {

class RouteModel;

// One undo step for an in-place edit of some rows: a move, an altitude, a parameter, actions...
// redo and undo swap the stored values in. Steps of one gesture (same gesture number, not 0)
// that do the same kind of edit to the same rows merge: the step keeps the values the gesture
// started from and takes the latest ones. This is the only way edits merge (see RouteEditor.h).
class EditSegmentsCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x5302;

    // rows sorted and unique, before/after in the same order. gesture 0: never merges.
    EditSegmentsCommand(RouteModel *model, std::vector<int> rows, std::vector<Segment> before, std::vector<Segment> after,
                        const QString &text, QString kind = {}, int gesture = 0);
    void redo() override;
    void undo() override;
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    RouteModel *m_model;
    std::vector<int> m_rows;
    std::vector<Segment> m_before;
    std::vector<Segment> m_after;
    QString m_kind;
    int m_gesture;
};

} // namespace sortie::mission
