#pragma once

#include <QObject>

#include <functional>

class QAbstractItemModel;

namespace sortie::i18n {

// Calls `refresh` each time the application's language changes (a translator installed or removed
// sends QEvent::LanguageChange to the application), for as long as `owner` lives. Objects that hold
// or compute translated words re-emit them there, so that the views read them again.
void onLanguageChange(QObject *owner, std::function<void()> refresh);

// For a model whose data() translates as it answers: every row's data is announced changed.
void refreshOnLanguageChange(QAbstractItemModel *model);

} // namespace sortie::i18n
