#pragma once

#include "RouteAnalyzer.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SegmentEditorModel.h"
#include "WaypointActionsModel.h"
#include "SegmentPreview.h"

#include <QItemSelectionModel>
#include <QObject>
#include <QUndoStack>
#include <QUrl>

namespace sortie::client {

// The route open for editing, with nothing of the network in it: the model the map and the table
// both show, its undo stack, its editor (the one way to change it: every gesture, cell and
// button calls `editor`), the selection (rows an edit adds become it), analysis (statistics,
// validation) and import/export of files.
class RouteDocument : public QObject
{
    Q_OBJECT
    Q_PROPERTY(sortie::mission::RouteModel *model READ model CONSTANT)
    Q_PROPERTY(sortie::mission::RouteEditor *editor READ editor CONSTANT)
    Q_PROPERTY(QUndoStack *undoStack READ undoStack CONSTANT)
    Q_PROPERTY(QItemSelectionModel *selection READ selection CONSTANT)
    Q_PROPERTY(sortie::mission::RouteAnalyzer *analyzer READ analyzer CONSTANT)
    // The current segment's parameters, as the editor the panel draws (follows currentRow).
    Q_PROPERTY(sortie::mission::SegmentEditorModel *segmentEditor READ segmentEditor CONSTANT)
    Q_PROPERTY(sortie::mission::WaypointActionsModel *actionEditor READ actionEditor CONSTANT)
    Q_PROPERTY(bool modified READ isModified NOTIFY modifiedChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY undoChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY undoChanged)
    Q_PROPERTY(QString undoText READ undoText NOTIFY undoChanged)
    Q_PROPERTY(QString redoText READ redoText NOTIFY undoChanged)
    Q_PROPERTY(QList<int> selectedRows READ selectedRows NOTIFY selectedRowsChanged)
    Q_PROPERTY(QString message READ message NOTIFY messageChanged)
    Q_PROPERTY(int currentRow READ currentRow NOTIFY currentChanged)
    // The current segment, unless it is a waypoint: its figure (an area's corners, a corridor's
    // line, a circle's centre), the path it flies (QGeoCoordinates, from `preview`) and its
    // parameters by wire name; empty otherwise.
    Q_PROPERTY(QVariantList scanPolygon READ scanPolygon NOTIFY previewChanged)
    Q_PROPERTY(QVariantList scanPath READ scanPath NOTIFY previewChanged)
    Q_PROPERTY(QString scanProblem READ scanProblem NOTIFY previewChanged)
    // The current segment's figure and path, planned at most once per frame while it is edited.
    Q_PROPERTY(sortie::mission::SegmentPreview *preview READ preview CONSTANT)

public:
    explicit RouteDocument(QObject *parent = nullptr);

    mission::RouteModel *model() { return &m_model; }
    mission::RouteEditor *editor() { return &m_editor; }
    QUndoStack *undoStack() { return &m_undo; }
    QItemSelectionModel *selection() { return &m_selection; }
    mission::RouteAnalyzer *analyzer() { return &m_analyzer; }
    mission::SegmentEditorModel *segmentEditor() { return &m_segmentEditor; }
    mission::WaypointActionsModel *actionEditor() { return &m_actionEditor; }
    mission::SegmentPreview *preview() { return &m_preview; }
    const mission::Route &route() const { return m_model.route(); }
    // The route as last loaded (opened, saved, followed from the server): what "unsaved edits"
    // are measured against, and what both sides of a conflict started from.
    const mission::Route &baseline() const { return m_baseline; }

    bool isModified() const { return !m_undo.isClean(); }
    bool canUndo() const { return m_undo.canUndo(); }
    bool canRedo() const { return m_undo.canRedo(); }
    QString undoText() const { return m_undo.undoText(); }
    QString redoText() const { return m_undo.redoText(); }
    QList<int> selectedRows() const;
    QString message() const { return m_message; }
    int currentRow() const;
    QVariantList scanPolygon() const;
    QVariantList scanPath() const;
    QString scanProblem() const;

    // Replaces the whole route (opened from the server or reloaded): not undoable, marks clean.
    void load(mission::Route route);
    // Makes `route` the document and its new baseline, marked clean, without losing what undo can
    // bring back: when the document has unsaved edits or an undo history, this is one undo step
    // (`text`) that undo takes back, route and baseline together, edits and all; otherwise load().
    void open(mission::Route route, const QString &text);
    void markSaved() { m_undo.setClean(); }

    Q_INVOKABLE void selectRows(const QList<int> &rows);
    // A click on a row of the table: selects it; Ctrl toggles it, Shift extends from the current row.
    Q_INVOKABLE void clickRow(int row, int modifiers);
    Q_INVOKABLE void undo() { m_undo.undo(); }
    Q_INVOKABLE void redo() { m_undo.redo(); }

    // Files: .sortie, .plan, WPL (.waypoints/.txt), KML. An import is one undo step and keeps the
    // route's server identity, so saving it updates the route that is open.
    Q_INVOKABLE bool importFile(const QUrl &file);
    Q_INVOKABLE bool exportFile(const QUrl &file);

signals:
    void modifiedChanged();
    void undoChanged();
    void selectedRowsChanged();
    void messageChanged();
    void currentChanged();
    void previewChanged();
    // load() replaced the route: a new baseline (what "unsaved edits" are measured against).
    void loaded();
    // baseline() changed: by load(), or by open() and its undo and redo.
    void baselineChanged();

private:
    friend class OpenRouteCommand;
    void setMessage(const QString &message);
    void setBaseline(mission::Route baseline);

    mission::RouteModel m_model;
    QUndoStack m_undo;
    mission::RouteEditor m_editor;
    QItemSelectionModel m_selection;
    mission::RouteAnalyzer m_analyzer;
    mission::SegmentEditorModel m_segmentEditor;
    mission::WaypointActionsModel m_actionEditor;
    mission::SegmentPreview m_preview;
    mission::Route m_baseline;
    QString m_message;
};

} // namespace sortie::client
