#pragma once

#include "Theme.h"

#include <QColor>
#include <QPointer>
#include <QQuickPaintedItem>
#include <QtQml/qqmlregistration.h>

#include <cmath>

namespace sortie::ui {

// The artificial horizon: sky over ground turned by the roll and shifted by the pitch, a pitch
// ladder every 10°, a roll scale with its pointer, and the fixed aircraft symbol. Drawn with
// QPainter, so it renders offscreen too. Without attitude (NaN) it shows a grey face and says so.
class AttitudeIndicator : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(double roll READ roll WRITE setRoll NOTIFY attitudeChanged)   // deg, right wing down positive
    Q_PROPERTY(double pitch READ pitch WRITE setPitch NOTIFY attitudeChanged) // deg, nose up positive
    // Its words and the face come from the theme (the light scheme without one).
    Q_PROPERTY(sortie::ui::Theme *theme READ theme WRITE setTheme NOTIFY themeChanged)

public:
    explicit AttitudeIndicator(QQuickItem *parent = nullptr);

    double roll() const { return m_roll; }
    void setRoll(double degrees);
    double pitch() const { return m_pitch; }
    void setPitch(double degrees);
    Theme *theme() const { return m_theme; }
    void setTheme(Theme *theme);
    bool hasAttitude() const { return std::isfinite(m_roll) && std::isfinite(m_pitch); }

    void paint(QPainter *painter) override;

signals:
    void attitudeChanged();
    void themeChanged();

private:
    double m_roll = qQNaN();
    double m_pitch = qQNaN();
    QPointer<Theme> m_theme;
};

} // namespace sortie::ui
