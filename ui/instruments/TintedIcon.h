#pragma once

#include <QColor>
#include <QImage>
#include <QQuickPaintedItem>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// One of the built-in symbolic icons (resources/icons/adwaita, ":/sortie/icons/NAME.png") drawn in
// a colour: its shape (alpha) kept, its grey replaced by `color`, so an icon reads on every
// scheme and says its level by its colour. Painted, so it draws offscreen too. An unknown name
// draws nothing and says so once (sortie.ui.icons).
class TintedIcon : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString name READ name WRITE setName NOTIFY nameChanged)
    Q_PROPERTY(QColor color READ color WRITE setColor NOTIFY colorChanged)
    Q_PROPERTY(bool valid READ isValid NOTIFY nameChanged)

public:
    explicit TintedIcon(QQuickItem *parent = nullptr);

    QString name() const { return m_name; }
    void setName(const QString &name);
    QColor color() const { return m_color; }
    void setColor(const QColor &color);
    bool isValid() const { return !m_source.isNull(); }

    // The icon `name` in `colour`, `size` device pixels square (null for an unknown name).
    static QImage tinted(const QString &name, const QColor &colour, int size);

    void paint(QPainter *painter) override;

signals:
    void nameChanged();
    void colorChanged();

private:
    QString m_name;
    QColor m_color;
    QImage m_source;
};

} // namespace sortie::ui
