// Everything the map classes share about their files, in one include for programs written
// against an earlier version: the frame of an observation (observation_frame.h), the views'
// archive (view_archive.h), what a view-based map shows (view_display.h) and saving and loading
// with a checksum (map_file.h). New code includes the header it uses.
#pragma once

#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/observation_frame.h"
#include "mrpt_plugins/view_archive.h"
#include "mrpt_plugins/view_display.h"
