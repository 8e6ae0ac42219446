#include "LayOutOnAdd.h"

namespace sortie::ui {

namespace {
// Outer layouts first: each places its children, then the layouts among them place theirs.
void layOutTree(QQuickItem *item)
{
    if (item->inherits("QQuickLayout"))
        item->ensurePolished();
    for (QQuickItem *child : item->childItems())
        layOutTree(child);
}
} // namespace

LayOutOnAdd::LayOutOnAdd(QObject *repeater)
    : QObject(repeater)
{
    // QQuickRepeater is private API; its itemAdded signal is public QML.
    connect(repeater, SIGNAL(itemAdded(int,QQuickItem*)), this, SLOT(layOut()));
}

void LayOutOnAdd::setLayout(QQuickItem *layout)
{
    if (layout == m_layout)
        return;
    m_layout = layout;
    emit layoutChanged();
}

void LayOutOnAdd::layOut()
{
    if (!m_layout)
        return;
    layOutTree(m_layout);
    // It grew: the layouts around it (a panel's column) place it and whatever follows it anew, or the
    // new rows would lie under the next item for a moment.
    for (QQuickItem *up = m_layout->parentItem(); up; up = up->parentItem())
        if (up->inherits("QQuickLayout"))
            up->ensurePolished();
}

} // namespace sortie::ui
