#include "RouteAnalyzer.h"
#include "LanguageChange.h"

#include "RouteModel.h"
#include "ValidationIssueModel.h"

#include <algorithm>

namespace sortie::mission {

RouteAnalyzer::RouteAnalyzer(const RouteModel *model, QObject *parent)
    : QObject(parent), m_model(model), m_issues(new ValidationIssueModel(this))
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(50);
    connect(&m_timer, &QTimer::timeout, this, &RouteAnalyzer::recomputeNow);
    connect(model, &RouteModel::routeEdited, this, &RouteAnalyzer::schedule);
    // The issues' and the rules' words (the endurance's "no profile") are made by the analysis:
    // after a language change it runs again, as after an edit.
    i18n::onLanguageChange(this, [this] { schedule(); });
    recomputeNow();
}

void RouteAnalyzer::addRule(RouteRule *rule)
{
    m_rules.emplace_back(rule);
    connect(rule, &RouteRule::changed, this, &RouteAnalyzer::schedule);
    schedule();
}

void RouteAnalyzer::setDelay(int milliseconds)
{
    m_timer.setInterval(milliseconds);
}

void RouteAnalyzer::schedule()
{
    if (m_timer.isActive())
        return;  // already due: this edit will be included
    m_timer.start();
    emit pendingChanged();
}

void RouteAnalyzer::recomputeNow()
{
    const bool wasPending = m_timer.isActive();
    m_timer.stop();
    ++m_recomputes;
    RouteStatistics st = computeStatistics(m_model->route(), &m_scans);
    ValidationReport report = validateRoute(m_model->route(), &m_scans);
    if (!m_rules.empty()) {
        for (const auto &rule : m_rules)
            if (rule)
                rule->check(m_model->route(), &m_scans, report.issues);
        std::stable_sort(report.issues.begin(), report.issues.end(),
                         [](const ValidationIssue &a, const ValidationIssue &b) { return a.segment < b.segment; });
    }
    m_scans.retainRecentlyUsed();
    const bool statsChanged = !(st == m_statistics);
    const bool validationDiffers = !(report == m_validation);
    m_statistics = std::move(st);
    m_validation = std::move(report);
    m_issues->setReport(m_validation);
    if (statsChanged)
        emit statisticsChanged();
    if (validationDiffers)
        emit validationChanged();
    if (wasPending)
        emit pendingChanged();
    emit recomputed();
}

} // namespace sortie::mission
