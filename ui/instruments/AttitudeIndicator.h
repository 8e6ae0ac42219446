#pragma once

#include <QColor>
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
    Q_PROPERTY(QColor textColor READ textColor WRITE setTextColor NOTIFY textColorChanged)

public:
    explicit AttitudeIndicator(QQuickItem *parent = nullptr);

    double roll() const { return m_roll; }
    void setRoll(double degrees);
    double pitch() const { return m_pitch; }
    void setPitch(double degrees);
    QColor textColor() const { return m_text; }
    void setTextColor(const QColor &color);
    bool hasAttitude() const { return std::isfinite(m_roll) && std::isfinite(m_pitch); }

    void paint(QPainter *painter) override;

signals:
    void attitudeChanged();
    void textColorChanged();

private:
    double m_roll = qQNaN();
    double m_pitch = qQNaN();
    QColor m_text = Qt::black;
};

} // namespace sortie::ui
