#pragma once

#include "Segment.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVariantList>

#include <optional>

namespace sortie::mission {

class RouteEditor;
class RouteModel;

// The current segment's figure (corners, centre line, centre) and the path it flies, for the map,
// planned the way the server processes it (area scans by the AreaScanPlanner, every other tool by
// the SegmentPlanner sortie-sim uses). Coalesced: however many edits arrive (a drag sends one per
// mouse move), it plans at most once per frame and emits changed() once; an edit of another row
// costs nothing. Reading a property plans at once if an edit is pending, so C++ callers and tests
// always see the current state.
class SegmentPreview : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QVariantList figure READ figure NOTIFY changed)   // QGeoCoordinates
    Q_PROPERTY(QVariantList path READ path NOTIFY changed)       // QGeoCoordinates, in flight order
    Q_PROPERTY(QString problem READ problem NOTIFY changed)     // why there is no path, "" when there is
    Q_PROPERTY(int planCount READ planCount NOTIFY changed)     // plans made so far (coalescing shows here)
    // "polygon", "polyline", "point", "circle"; "" for a waypoint or no row.
    Q_PROPERTY(QString figureType READ figureType NOTIFY changed)
    Q_PROPERTY(double radius READ radius NOTIFY changed)         // a circle's, metres; 0 otherwise

public:
    static constexpr int kFrameMs = 16;

    SegmentPreview(RouteModel *model, RouteEditor *editor, QObject *parent = nullptr);

    void setRow(int row);
    int row() const { return m_row; }
    QVariantList figure() const;
    QVariantList path() const;
    QString problem() const;
    int planCount() const { return m_planCount; }
    QString figureType() const;
    double radius() const;

signals:
    void changed();

private:
    void schedule();
    void refresh() const;  // plans when the segment changed since the last plan

    QPointer<RouteModel> m_model;
    QPointer<RouteEditor> m_editor;
    int m_row = -1;
    QTimer m_frame;
    QElapsedTimer m_sinceLast;
    mutable bool m_dirty = true;
    mutable std::optional<Segment> m_planned;  // the segment the results belong to
    mutable QVariantList m_figure;
    mutable QVariantList m_path;
    mutable QString m_problem;
    mutable QString m_figureType;
    mutable double m_radius = 0.0;
    mutable int m_planCount = 0;
    mutable int m_version = 0;  // of what the properties hold
    int m_emitted = 0;          // the version changed() last announced
};

} // namespace sortie::mission
