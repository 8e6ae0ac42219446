#pragma once

#include "VciTypes.h"

#include <QMetaType>
#include <QString>

#include <nlohmann/json.hpp>

namespace sortie::vci {

// The outcome of one request: the vehicle's status and body, or why there is none. `ok()` is true for
// a 2xx answer only. `message` is written for an operator ("PUT /state/armed: the vehicle answered
// 400 Bad Request: no 3D GPS fix").
struct VciResult
{
    enum class Error {
        None,           // a 2xx answer
        Status,         // the vehicle answered with a non-2xx status (see status(), body)
        Timeout,        // no answer within the request's timeout
        NotConnected,   // there was no connection to send it on
        ConnectionLost, // the connection dropped before the answer came
        BadResponse,    // the answer could not be parsed
        InvalidRequest, // Sortie refused to send it (a malformed URI)
    };

    Error error = Error::None;
    int statusCode = 0;      // 0 when there was no answer
    QString reason;
    nlohmann::json body;     // the answer's JSON body, or null
    QString message;         // empty when ok()

    bool ok() const { return error == Error::None; }
    VciStatus status() const { return VciStatus(statusCode); }
};

const char *toString(VciResult::Error error);

} // namespace sortie::vci

Q_DECLARE_METATYPE(sortie::vci::VciResult)
Q_DECLARE_METATYPE(nlohmann::json)
