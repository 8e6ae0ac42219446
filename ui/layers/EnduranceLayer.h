#pragma once

#include "MapLayer.h"

#include <QVariant>

namespace sortie::ui {

// Where the open route's battery runs out, on the map: each battery change (a battery glyph, green
// where the route lands there, amber where the operator still has to plan that landing) and the
// point of no return (a red diamond): beyond it, flying straight home no longer lands with the
// reserve. It draws what RouteEndurance computed (`changePoints`, `pointOfNoReturn`): positions
// in, marks out, no rule of its own.
class EnduranceLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    // [{latitude, longitude, planned, waypoint, ...}], RouteEndurance.changePoints.
    Q_PROPERTY(QVariantList changePoints READ changePoints WRITE setChangePoints NOTIFY marksChanged)
    // {latitude, longitude, ...} or null/undefined, RouteEndurance.pointOfNoReturn.
    Q_PROPERTY(QVariant pointOfNoReturn READ pointOfNoReturn WRITE setPointOfNoReturn NOTIFY marksChanged)
    Q_PROPERTY(int markCount READ markCount NOTIFY marksChanged)

public:
    explicit EnduranceLayer(QQuickItem *parent = nullptr);

    QVariantList changePoints() const { return m_changes; }
    void setChangePoints(const QVariantList &points);
    QVariant pointOfNoReturn() const { return m_noReturn; }
    void setPointOfNoReturn(const QVariant &point);
    int markCount() const { return int(m_marks.size()); }
    // Where a mark is drawn, in this item's coordinates (for tests and tooltips); NaN when none.
    Q_INVOKABLE QPointF markPosition(int index) const;

    void paint(QPainter *painter) override;

    static QColor plannedColour() { return QColor(0x43, 0xa0, 0x47); }
    static QColor unplannedColour() { return QColor(0xfb, 0x8c, 0x00); }
    static QColor noReturnColour() { return QColor(0xe5, 0x39, 0x35); }

signals:
    void marksChanged();

protected:
    void onLanguageChanged() override { readMarks(); }

private:
    enum class Kind { PlannedChange, UnplannedChange, NoReturn };
    struct Mark
    {
        QGeoCoordinate position;
        Kind kind;
        QString label;
    };
    void readMarks();

    QVariantList m_changes;
    QVariant m_noReturn;
    std::vector<Mark> m_marks;
};

} // namespace sortie::ui
