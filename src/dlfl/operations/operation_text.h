#pragma once
// Operations written as text, the way `dlfl edit --op` takes them: "insert_edge corner1=0 corner2=2".

#include <string>
#include <string_view>
#include <utility>

#include <dlfl/parameters.h>

namespace dlfl {

/// Splits "NAME key=value key=value ..." into the name and its parameters, each value as text (resolved
/// later against the operation's declaration: a handle is its number, a point `x,y,z`, a list `a,b,c`, a
/// list of points `x,y,z;x,y,z`). A value may be quoted with ' or " to hold spaces. A dotted key fills a
/// nested parameter set: "subdivide scheme=honeycomb params.t=0.4". Throws ParameterError for a malformed
/// item or a key given twice, InvalidArgument for an empty text or an unterminated quote.
std::pair<std::string, Params> parse_operation_text(std::string_view text);

}  // namespace dlfl
