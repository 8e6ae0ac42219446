#pragma once

#include <QObject>
#include <QPointer>

namespace sortie::ui {

// A view that draws what a typed owner object holds (ZoneCrossingLayer the Airspace's crossings,
// EnduranceLayer the RouteEndurance's estimate, …) points `held` at `owner` and follows its
// `changed` signal with `read`, having let go of the owner before. False when `owner` already is
// the one held; the caller then reads once and says its property changed.
template<class Owner, class View, class Signal, class Slot>
bool followOwner(QPointer<Owner> &held, Owner *owner, View *view, Signal changed, Slot read)
{
    if (owner == held)
        return false;
    if (held)
        QObject::disconnect(held, nullptr, view, nullptr);
    held = owner;
    if (held)
        QObject::connect(held, changed, view, read);
    return true;
}

} // namespace sortie::ui
