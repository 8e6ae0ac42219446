#include "RouteDocument.h"

#include "AreaScanPlanner.h"
#include "MissionFiles.h"

#include <QFileInfo>
#include <QGeoCoordinate>

namespace sortie::client {

using namespace sortie::mission;

// open()'s undo step: swaps the model's route and the document's baseline with the ones it holds,
// so undo brings back the route that was open, its unsaved edits and what they were made against.
class OpenRouteCommand : public QUndoCommand
{
public:
    OpenRouteCommand(RouteDocument *document, Route route, const QString &text)
        : QUndoCommand(text), m_document(document), m_route(route), m_baseline(std::move(route))
    {
    }
    void redo() override
    {
        m_document->m_selection.clear();
        Route route = m_document->route();
        Route baseline = m_document->baseline();
        m_document->m_model.resetRoute(std::move(m_route));
        m_document->setBaseline(std::move(m_baseline));
        m_route = std::move(route);
        m_baseline = std::move(baseline);
    }
    void undo() override { redo(); } // a swap is its own inverse

private:
    RouteDocument *m_document;
    Route m_route;    // the route not in the model now
    Route m_baseline; // and the baseline that goes with it
};

RouteDocument::RouteDocument(QObject *parent)
    : QObject(parent)
    , m_editor(&m_model, &m_undo)
    , m_selection(&m_model)
    , m_analyzer(&m_model)
    , m_segmentEditor(&m_model, &m_editor)
    , m_actionEditor(&m_model, &m_editor)
    , m_preview(&m_model, &m_editor)
{
    connect(this, &RouteDocument::currentChanged, this, [this] {
        m_segmentEditor.setRow(currentRow());
        m_preview.setRow(currentRow());
    });
    connect(&m_preview, &SegmentPreview::changed, this, &RouteDocument::previewChanged);
    connect(&m_editor, &RouteEditor::rowsAdded, this, [this](int first, int count) {
        QList<int> rows;
        for (int r = first; r < first + count; ++r)
            rows << r;
        selectRows(rows);
    });
    connect(&m_editor, &RouteEditor::refused, this, &RouteDocument::setMessage);
    connect(&m_undo, &QUndoStack::cleanChanged, this, &RouteDocument::modifiedChanged);
    connect(&m_undo, &QUndoStack::indexChanged, this, &RouteDocument::undoChanged);
    connect(&m_undo, &QUndoStack::canUndoChanged, this, &RouteDocument::undoChanged);
    connect(&m_undo, &QUndoStack::canRedoChanged, this, &RouteDocument::undoChanged);
    connect(&m_selection, &QItemSelectionModel::selectionChanged, this, &RouteDocument::selectedRowsChanged);
    connect(&m_model, &QAbstractItemModel::modelReset, this, &RouteDocument::selectedRowsChanged);
    connect(&m_selection, &QItemSelectionModel::currentChanged, this, &RouteDocument::currentChanged);
    connect(&m_model, &RouteModel::routeEdited, this, &RouteDocument::currentChanged);
    // The action editor shows the current waypoint's actions and edits the selection's.
    const auto selectActions = [this] {
        QList<int> rows = selectedRows();
        if (const int current = currentRow(); rows.removeOne(current) || rows.isEmpty())
            rows.prepend(current);
        rows.removeAll(-1);
        m_actionEditor.setRows(rows);
    };
    connect(this, &RouteDocument::selectedRowsChanged, this, selectActions);
    connect(this, &RouteDocument::currentChanged, this, selectActions);
}

int RouteDocument::currentRow() const
{
    const QModelIndex current = m_selection.currentIndex();
    return current.isValid() && current.row() < m_model.count() ? current.row() : -1;
}

QVariantList RouteDocument::scanPolygon() const
{
    return m_preview.figure();
}

QVariantList RouteDocument::scanPath() const
{
    return m_preview.path();
}

QString RouteDocument::scanProblem() const
{
    return m_preview.problem();
}

QList<int> RouteDocument::selectedRows() const
{
    QList<int> rows;
    for (const QModelIndex &index : m_selection.selectedRows())
        rows.append(index.row());
    std::sort(rows.begin(), rows.end());
    return rows;
}

void RouteDocument::load(Route route)
{
    m_selection.clear();
    m_model.resetRoute(route);
    m_undo.clear();
    m_undo.setClean();
    m_analyzer.recomputeNow();
    setBaseline(std::move(route));
    emit modifiedChanged();
    emit undoChanged();
    emit loaded();
}

void RouteDocument::open(Route route, const QString &text)
{
    if (!isModified() && !canUndo())
        return load(std::move(route));
    m_undo.push(new OpenRouteCommand(this, std::move(route), text));
    m_undo.setClean();
    m_analyzer.recomputeNow();
}

void RouteDocument::setBaseline(Route baseline)
{
    m_baseline = std::move(baseline);
    emit baselineChanged();
}

void RouteDocument::selectRows(const QList<int> &rows)
{
    QItemSelection selection;
    for (int row : rows) {
        if (row >= 0 && row < m_model.count())
            selection.select(m_model.index(row), m_model.index(row));
    }
    m_selection.select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    if (!rows.isEmpty() && rows.last() >= 0 && rows.last() < m_model.count())
        m_selection.setCurrentIndex(m_model.index(rows.last()), QItemSelectionModel::NoUpdate);
}

void RouteDocument::clickRow(int row, int modifiers)
{
    if (row < 0 || row >= m_model.count())
        return;
    const QModelIndex index = m_model.index(row);
    const auto mods = Qt::KeyboardModifiers(modifiers);
    if (mods & Qt::ControlModifier) {
        m_selection.setCurrentIndex(index, QItemSelectionModel::Toggle | QItemSelectionModel::Rows);
    } else if ((mods & Qt::ShiftModifier) && currentRow() >= 0) {
        const int from = currentRow();
        m_selection.select(QItemSelection(m_model.index(std::min(from, row)), m_model.index(std::max(from, row))),
                           QItemSelectionModel::Select | QItemSelectionModel::Rows);
        m_selection.setCurrentIndex(index, QItemSelectionModel::NoUpdate);
    } else {
        selectRows({row});
    }
}

bool RouteDocument::importFile(const QUrl &file)
{
    const QString path = file.isLocalFile() ? file.toLocalFile() : file.toString();
    auto loaded = formats::loadMission(path);
    if (!loaded) {
        setMessage(tr("Import failed: %1").arg(loaded.error().toString()));
        return false;
    }
    if (loaded->mission.routes.empty()) {
        setMessage(tr("Import failed: %1 holds no route.").arg(QFileInfo(path).fileName()));
        return false;
    }
    Route route = loaded->mission.routes.front();
    route.origin = m_model.route().origin; // saving updates the route that is open
    if (!m_model.route().settings.name.isEmpty())
        route.settings.name = m_model.route().settings.name;
    m_selection.clear();
    m_editor.replaceRoute(std::move(route), tr("Import %1").arg(QFileInfo(path).fileName()));
    QString text = tr("Imported %n segment(s) from %1.", nullptr, m_model.count()).arg(QFileInfo(path).fileName());
    // The editor holds one route: say so rather than drop a file's other routes unseen.
    if (loaded->mission.routes.size() > 1)
        text += QLatin1Char(' ') + tr("The file holds %1 routes; this is the first (\"%2\").")
                                       .arg(loaded->mission.routes.size()).arg(loaded->mission.routes.front().settings.name);
    if (!loaded->notices.isEmpty())
        text += QLatin1Char(' ') + loaded->notices.join(QLatin1Char(' '));
    setMessage(text);
    return true;
}

bool RouteDocument::exportFile(const QUrl &file)
{
    const QString path = file.isLocalFile() ? file.toLocalFile() : file.toString();
    Mission mission;
    mission.name = m_model.route().settings.name;
    mission.routes.push_back(m_model.route());
    auto saved = formats::saveMission(mission, path);
    if (!saved) {
        setMessage(tr("Export failed: %1").arg(saved.error().toString()));
        return false;
    }
    QString text = tr("Exported to %1.").arg(QFileInfo(path).fileName());
    if (!saved->isEmpty())
        text += QLatin1Char(' ') + tr("Not representable there: %1").arg(saved->join(QStringLiteral("; ")));
    setMessage(text);
    return true;
}

void RouteDocument::setMessage(const QString &message)
{
    m_message = message;
    emit messageChanged();
}

} // namespace sortie::client
