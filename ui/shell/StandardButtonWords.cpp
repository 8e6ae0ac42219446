#include "StandardButtonWords.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QMetaMethod>
#include <QObject>
#include <QVariant>

namespace sortie::ui {

Q_LOGGING_CATEGORY(lcStandardButtons, "sortie.ui.translations.buttons")

namespace {
// QPlatformDialogHelper::StandardButton's values and the English Qt words them with (context
// QPlatformTheme), which qtbase_<lang>.qm translates. The '&' marks a mnemonic, dropped as the box does.
struct Word
{
    int button;
    const char *english;
};
constexpr Word kWords[] = {
    {0x00000400, "OK"},
    {0x00000800, "Save"},
    {0x00001000, "Save All"}, // i18n: not text (Qt's own word, translated by qtbase_<lang>.qm)
    {0x00002000, "Open"},
    {0x00004000, "&Yes"},
    {0x00008000, "Yes to &All"}, // i18n: not text (Qt's own word, translated by qtbase_<lang>.qm)
    {0x00010000, "&No"},
    {0x00020000, "N&o to All"}, // i18n: not text (Qt's own word, translated by qtbase_<lang>.qm)
    {0x00040000, "Abort"},
    {0x00080000, "Retry"},
    {0x00100000, "Ignore"},
    {0x00200000, "Close"},
    {0x00400000, "Cancel"},
    {0x00800000, "Discard"},
    {0x01000000, "Help"},
    {0x02000000, "Apply"},
    {0x04000000, "Reset"},
    {0x08000000, "Restore Defaults"}, // i18n: not text (Qt's own word, translated by qtbase_<lang>.qm)
};

// The box's button for a standard button, through its invokable standardButton() (the type is
// private to Qt Quick Templates).
QObject *standardButton(QObject *box, const QMetaMethod &lookup, int button)
{
    QObject *found = nullptr;
    lookup.invoke(box, Qt::DirectConnection, QGenericReturnArgument("QQuickAbstractButton*", &found),
                  QGenericArgument("QPlatformDialogHelper::StandardButton", &button));
    return found;
}
} // namespace

void rewordStandardButtons(QObject *root)
{
    if (!root)
        return;
    const QList<QObject *> objects = root->findChildren<QObject *>();
    for (QObject *box : objects) {
        if (!box->inherits("QQuickDialogButtonBox")) // also its QML types (DialogButtonBox_QMLTYPE_n)
            continue;
        const int index = box->metaObject()->indexOfMethod("standardButton(QPlatformDialogHelper::StandardButton)");
        if (index < 0) {
            qCWarning(lcStandardButtons) << "a dialog button box without standardButton(): its buttons keep their words";
            continue;
        }
        const QMetaMethod lookup = box->metaObject()->method(index);
        for (const Word &word : kWords) {
            if (QObject *button = standardButton(box, lookup, word.button))
                button->setProperty("text", QCoreApplication::translate("QPlatformTheme", word.english).remove(QLatin1Char('&')));
        }
    }
}

} // namespace sortie::ui
