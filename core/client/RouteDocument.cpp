#include "RouteDocument.h"

#include "MissionFiles.h"

#include <QFileInfo>
#include <QGeoCoordinate>

namespace sortie::client {

using namespace sortie::mission;

RouteDocument::RouteDocument(QObject *parent)
    : QObject(parent)
    , m_editor(&m_model, &m_undo)
    , m_selection(&m_model)
    , m_analyzer(&m_model)
{
    m_model.setUndoStack(&m_undo);
    connect(&m_undo, &QUndoStack::cleanChanged, this, &RouteDocument::modifiedChanged);
    connect(&m_undo, &QUndoStack::indexChanged, this, &RouteDocument::undoChanged);
    connect(&m_undo, &QUndoStack::canUndoChanged, this, &RouteDocument::undoChanged);
    connect(&m_undo, &QUndoStack::canRedoChanged, this, &RouteDocument::undoChanged);
    connect(&m_selection, &QItemSelectionModel::selectionChanged, this, &RouteDocument::selectedRowsChanged);
    connect(&m_model, &QAbstractItemModel::modelReset, this, &RouteDocument::selectedRowsChanged);
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
    m_model.resetRoute(std::move(route));
    m_undo.clear();
    m_undo.setClean();
    m_analyzer.recomputeNow();
    emit modifiedChanged();
    emit undoChanged();
}

int RouteDocument::addWaypoint(double latitude, double longitude)
{
    const int row = m_editor.addWaypoint(latitude, longitude);
    if (row >= 0)
        selectRows({row});
    return row;
}

int RouteDocument::insertWaypoint(int leg, double latitude, double longitude)
{
    if (leg < 0 || leg + 1 > m_model.count())
        return -1;
    const int row = m_editor.insertWaypoint(leg + 1, latitude, longitude);
    if (row >= 0)
        selectRows({row});
    return row;
}

void RouteDocument::moveWaypoints(const QVariantList &rows, const QVariantList &coordinates)
{
    if (rows.size() != coordinates.size() || rows.isEmpty())
        return;
    m_undo.beginMacro(rows.size() == 1 ? tr("Move waypoint %1").arg(rows.first().toInt() + 1)
                                       : tr("Move %n waypoint(s)", nullptr, int(rows.size())));
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const QGeoCoordinate c = coordinates[i].value<QGeoCoordinate>();
        if (c.isValid())
            m_editor.moveWaypoint(rows[i].toInt(), c.latitude(), c.longitude());
    }
    m_undo.endMacro();
}

void RouteDocument::removeSelected()
{
    const QList<int> rows = selectedRows();
    if (rows.isEmpty())
        return;
    m_selection.clear();
    m_editor.removeRows(rows);
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
