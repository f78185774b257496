// Internal to job/: the declarations of the option table that live outside
// option_table.cpp, by concept, and the FIELD macro every declaration uses.
#pragma once

#include <vector>

#include "job/option_table.h"

// The field an option sets, as a function of the options, so that one declaration names
// it once for reading and writing.
#define FIELD(member) [](RenderCommandOptions& o) -> auto& { return o.member; }

namespace penumbra {

// Which cameras and instants an image shows: views (option_table_views.cpp), the
// timeline (an instant or an exposure) and frames.
void add_view_options(std::vector<OptionDecl>& t);
void add_timeline_options(std::vector<OptionDecl>& t);
void add_frame_options(std::vector<OptionDecl>& t);

}  // namespace penumbra
