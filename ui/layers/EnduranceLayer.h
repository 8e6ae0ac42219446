#pragma once

#include "MapLayer.h"

#include <QPointer>

namespace sortie::endurance {
class RouteEndurance;
}

namespace sortie::ui {

// Where the open route's battery runs out, on the map: each battery change (a battery glyph, green
// where the route lands there, amber where the operator still has to plan that landing) and the
// point of no return (a red diamond): beyond it, flying straight home no longer lands with the
// reserve. It draws what RouteEndurance estimated (its battery changes and point of no return):
// positions in, marks out, no rule of its own.
class EnduranceLayer : public MapLayer
{
    Q_OBJECT
    Q_MOC_INCLUDE("RouteEndurance.h")
    QML_ELEMENT
    Q_PROPERTY(sortie::endurance::RouteEndurance *endurance READ endurance WRITE setEndurance NOTIFY enduranceChanged)
    Q_PROPERTY(int markCount READ markCount NOTIFY marksChanged)

public:
    explicit EnduranceLayer(QQuickItem *parent = nullptr);

    endurance::RouteEndurance *endurance() const;
    void setEndurance(endurance::RouteEndurance *endurance);
    int markCount() const { return int(m_marks.size()); }
    // Where a mark is drawn, in this item's coordinates (for tests and tooltips); NaN when none.
    Q_INVOKABLE QPointF markPosition(int index) const;

    void paint(QPainter *painter) override;

signals:
    void enduranceChanged();
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

    QPointer<endurance::RouteEndurance> m_endurance;
    std::vector<Mark> m_marks;
};

} // namespace sortie::ui
