#include "SetNfzChecksCommand.h"

#include "RouteModel.h"

#include <QCoreApplication>

namespace sortie::mission {

namespace {
QString textOf(bool aerodromeChanged, bool on)
{
    const char *what = aerodromeChanged ? (on ? QT_TRANSLATE_NOOP("SetNfzChecksCommand", "Check aerodrome zones")
                                              : QT_TRANSLATE_NOOP("SetNfzChecksCommand", "Do not check aerodrome zones"))
                                        : (on ? QT_TRANSLATE_NOOP("SetNfzChecksCommand", "Check custom zones")
                                              : QT_TRANSLATE_NOOP("SetNfzChecksCommand", "Do not check custom zones"));
    return QCoreApplication::translate("SetNfzChecksCommand", what);
}
} // namespace

SetNfzChecksCommand::SetNfzChecksCommand(RouteModel *model, bool checkAerodrome, bool checkCustom)
    : m_model(model)
    , m_aerodromeBefore(model->settings().checkAerodromeNfz)
    , m_customBefore(model->settings().checkCustomNfz)
    , m_aerodromeAfter(checkAerodrome)
    , m_customAfter(checkCustom)
{
    const bool aerodromeChanged = m_aerodromeBefore != m_aerodromeAfter;
    setText(textOf(aerodromeChanged, aerodromeChanged ? m_aerodromeAfter : m_customAfter));
}

void SetNfzChecksCommand::redo()
{
    apply(m_aerodromeAfter, m_customAfter);
}

void SetNfzChecksCommand::undo()
{
    apply(m_aerodromeBefore, m_customBefore);
}

void SetNfzChecksCommand::apply(bool aerodrome, bool custom)
{
    RouteSettings settings = m_model->settings();
    settings.checkAerodromeNfz = aerodrome;
    settings.checkCustomNfz = custom;
    m_model->setSettings(settings);
}

} // namespace sortie::mission
