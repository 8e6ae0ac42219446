#pragma once

#include "VciParser.h"

#include <nlohmann/json.hpp>

namespace sortie::vci {

// One JSON object per message or error, for sortie-dump's JSON-lines output:
//   {"offset":0,"size":97,"kind":"request","verb":"NOTIFY","uri":"/telemetry/position",
//    "headers":[["Content-Type","application/json"]],"body":{...}}
//   {"offset":97,"kind":"response","status":200,"reason":"OK","headers":[],...}
//   {"offset":180,"kind":"error","error":"bad JSON","message":"...","verb":"PUT","uri":"/x","reply":400}
// A non-JSON body appears as "rawBody" (a string; bytes that are not UTF-8 become U+FFFD when printed).
nlohmann::json vciDumpLine(const VciMessage &message);
nlohmann::json vciDumpLine(const VciParseError &error);
nlohmann::json vciDumpLine(const VciParser::Result &result);

} // namespace sortie::vci
