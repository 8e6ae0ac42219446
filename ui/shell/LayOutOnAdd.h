#pragma once

#include <QObject>
#include <QPointer>
#include <QQuickItem>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// Lays a layout out the moment a Repeater in it adds an item, rather than when the next frame is
// drawn, and the layouts around it too. Until then the new item, and every layout inside it, stands
// at its layout's corner on top of the others (and past the end of a panel that has not grown yet,
// under the next item), and a click in that moment lands in whichever is on top (a freshly added
// waypoint action's fields: tst_uiflows actionsAtAWaypoint). QML 6.4 cannot call Item.ensurePolished() itself
// (a 6.3 revision: "Type error"). Use: Repeater { LayOutOnAdd.layout: theLayout; ... }
class LayOutOnAdd : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("LayOutOnAdd is attached to a Repeater")
    QML_ATTACHED(LayOutOnAdd)
    Q_PROPERTY(QQuickItem *layout READ layout WRITE setLayout NOTIFY layoutChanged)

public:
    explicit LayOutOnAdd(QObject *repeater);
    static LayOutOnAdd *qmlAttachedProperties(QObject *repeater) { return new LayOutOnAdd(repeater); }

    QQuickItem *layout() const { return m_layout; }
    void setLayout(QQuickItem *layout);

signals:
    void layoutChanged();

private slots:
    void layOut();

private:
    QPointer<QQuickItem> m_layout;
};

} // namespace sortie::ui
