#include "SegmentPreview.h"

#include "AreaScanPlanner.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SegmentPlanning.h"

#include <QGeoCoordinate>

namespace sortie::mission {

namespace {
void append(QVariantList &list, const GeoPoint &p)
{
    list.append(QVariant::fromValue(QGeoCoordinate(p.latitude, p.longitude)));
}
} // namespace

SegmentPreview::SegmentPreview(RouteModel *model, RouteEditor *editor, QObject *parent)
    : QObject(parent), m_model(model), m_editor(editor)
{
    m_frame.setSingleShot(true);
    connect(&m_frame, &QTimer::timeout, this, [this] {
        refresh();
        m_sinceLast.restart();
        if (m_version != m_emitted) {
            m_emitted = m_version;
            emit changed();
        }
    });
    connect(model, &RouteModel::routeEdited, this, &SegmentPreview::schedule);
    connect(model, &QAbstractItemModel::modelReset, this, &SegmentPreview::schedule);
    connect(editor, &RouteEditor::catalogChanged, this, &SegmentPreview::schedule);
    m_sinceLast.start();
}

void SegmentPreview::setRow(int row)
{
    if (row == m_row)
        return;
    m_row = row;
    m_dirty = true;
    m_planned.reset();
    refresh();
    m_emitted = m_version;
    emit changed();
}

void SegmentPreview::schedule()
{
    m_dirty = true;
    if (!m_frame.isActive())
        m_frame.start(int(std::max<qint64>(0, kFrameMs - m_sinceLast.elapsed())));
}

void SegmentPreview::refresh() const
{
    if (!m_dirty)
        return;
    m_dirty = false;
    const bool valid = m_model && m_row >= 0 && m_row < m_model->count();
    if (!valid || isWaypoint(m_model->segment(m_row))) {
        if (m_planned || !m_figure.isEmpty() || !m_path.isEmpty()) {
            m_planned.reset();
            m_figure.clear();
            m_path.clear();
            m_problem.clear();
            m_figureType.clear();
            m_radius = 0.0;
            ++m_version;
        }
        return;
    }
    const Segment &s = m_model->segment(m_row);
    if (m_planned && *m_planned == s)
        return;  // another row changed
    m_planned = s;
    ++m_planCount;
    ++m_version;
    m_figure.clear();
    m_path.clear();
    m_problem.clear();
    for (const GeoPoint &g : figureOf(s))
        append(m_figure, g);
    m_radius = 0.0;
    m_figureType = QStringLiteral("polygon");
    if (const AlgorithmSegment *a = asAlgorithmSegment(s)) {
        switch (a->figure) {
        case FigureType::Polygon: break;
        case FigureType::Polyline: m_figureType = QStringLiteral("polyline"); break;
        case FigureType::Circle:
            m_figureType = QStringLiteral("circle");
            m_radius = a->figureParameters.empty() ? 0.0 : a->figureParameters.front();
            break;
        default: m_figureType = QStringLiteral("point"); break;
        }
    }
    if (const AreaScan *scan = asAreaScan(s)) {
        const AreaScanOutcome o = planAreaScan(*scan);
        if (o.ok())
            for (const GeoPoint &g : o.plan->path)
                append(m_path, g);
        m_problem = o.message;
        return;
    }
    const SegmentPlanOutcome o = planAlgorithmSegment(std::get<AlgorithmSegment>(s), m_editor->catalog(),
                                                      planContextOf(m_model->settings()));
    if (!o.ok()) {
        m_problem = o.errors.empty() ? tr("This segment cannot be planned.") : o.errors.front();
        return;
    }
    for (const PlannedPoint &p : o.plan->points)
        append(m_path, p.position);
}

QVariantList SegmentPreview::figure() const
{
    refresh();
    return m_figure;
}

QVariantList SegmentPreview::path() const
{
    refresh();
    return m_path;
}

QString SegmentPreview::problem() const
{
    refresh();
    return m_problem;
}

QString SegmentPreview::figureType() const
{
    refresh();
    return m_figureType;
}

double SegmentPreview::radius() const
{
    refresh();
    return m_radius;
}

} // namespace sortie::mission
