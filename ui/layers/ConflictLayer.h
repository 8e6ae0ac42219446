#pragma once

#include "MapLayer.h"

#include <QVariant>

namespace sortie::ui {

// Where the open route would meet another vehicle: for each conflict RouteDeconfliction found, both
// vehicles' positions at the closest approach (the open route's a red ring, the other a red
// dot), joined by a red line, labelled with the time after the start and the separations. It draws
// what it is given (`conflicts`); the rule decides.
class ConflictLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    // RouteDeconfliction.conflicts: [{latitude, longitude, otherLatitude, otherLongitude, time, horizontal, vertical, otherVehicle}]
    Q_PROPERTY(QVariantList conflicts READ conflicts WRITE setConflicts NOTIFY conflictsChanged)
    Q_PROPERTY(int markCount READ markCount NOTIFY conflictsChanged)

public:
    explicit ConflictLayer(QQuickItem *parent = nullptr);

    QVariantList conflicts() const { return m_conflicts; }
    void setConflicts(const QVariantList &conflicts);
    int markCount() const { return int(m_marks.size()); }
    // Where a conflict's own position is drawn, in this item's coordinates (tests); NaN when none.
    Q_INVOKABLE QPointF markPosition(int index) const;

    void paint(QPainter *painter) override;

    static QColor colour() { return QColor(0xd5, 0x00, 0x00); }

signals:
    void conflictsChanged();

protected:
    void onLanguageChanged() override { readMarks(); }

private:
    // The marks and their labels (worded in the current language), from m_conflicts.
    void readMarks();

    struct Mark
    {
        QGeoCoordinate own, other;
        QString label;
    };

    QVariantList m_conflicts;
    std::vector<Mark> m_marks;
};

} // namespace sortie::ui
