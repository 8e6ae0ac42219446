#pragma once

#include "MapLayer.h"

#include <QPointer>

namespace sortie::deconfliction {
class RouteDeconfliction;
}

namespace sortie::ui {

// Where the open route would meet another vehicle: for each conflict RouteDeconfliction found, both
// vehicles' positions at the closest approach (the open route's a red ring, the other a red
// dot), joined by a red line, labelled with the time after the start and the separations. It draws
// the conflicts `deconfliction` found; the rule decides.
class ConflictLayer : public MapLayer
{
    Q_OBJECT
    Q_MOC_INCLUDE("RouteDeconfliction.h")
    QML_ELEMENT
    // The open route's conflicts (null without vehicles: nothing drawn).
    Q_PROPERTY(sortie::deconfliction::RouteDeconfliction *deconfliction READ deconfliction WRITE setDeconfliction NOTIFY deconflictionChanged)
    Q_PROPERTY(int markCount READ markCount NOTIFY conflictsChanged)

public:
    explicit ConflictLayer(QQuickItem *parent = nullptr);

    deconfliction::RouteDeconfliction *deconfliction() const;
    void setDeconfliction(deconfliction::RouteDeconfliction *deconfliction);
    int markCount() const { return int(m_marks.size()); }
    // Where a conflict's own position is drawn, in this item's coordinates (tests); NaN when none.
    Q_INVOKABLE QPointF markPosition(int index) const;

    void paint(QPainter *painter) override;

signals:
    void deconflictionChanged();
    void conflictsChanged();

protected:
    void onLanguageChanged() override { readMarks(); }

private:
    // The marks and their labels (worded in the current language), from the conflicts.
    void readMarks();

    struct Mark
    {
        QGeoCoordinate own, other;
        QString label;
    };

    QPointer<deconfliction::RouteDeconfliction> m_deconfliction;
    std::vector<Mark> m_marks;
};

} // namespace sortie::ui
