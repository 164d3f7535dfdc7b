// An NSI `volume` node as ANARI objects: the NanoVDB file's density grid as
// a `nanovdb` spatial field, rendered by a `transferFunction1D` volume whose
// colour is the volume shader's and whose opacity rises linearly over the
// grid's value range. OpenVDB (.vdb) files are reported, not read.
#pragma once

#include "GeometryBuilder.h"
#include "ResolvedScene.h"

#include <anari/anari.h>

namespace prism::nsi {

// The volume, or null with the reason reported (a missing or unreadable
// file, an OpenVDB file, a grid the file does not have).
ANARIVolume newNanoVdbVolume(
    ANARIDevice device, const VolumeItem &item, const ReportFunction &report);

} // namespace prism::nsi
