#pragma once
// Library-internal (GDAL types). GDAL's S57 driver puts every feature whose
// object class code (FRID OBJL) S-57 does not define into a layer named
// "Generic". A real ENC holds none: one there is a damaged cell (a flipped
// byte turned a coastline or a sounding into code 180 and it left its layer,
// exit 0) or one beyond S-57 edition 3.1. Either way nobody can say what the
// object is, so it is not read as a chart.

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <string>

#include "deepguide/core/error.hpp"

namespace deepguide {

/// InputError naming the first feature of an unknown object class, if any.
/// `shown_path`: the cell as messages name it.
inline void refuse_unknown_object_classes(GDALDataset& ds, const std::string& shown_path) {
  OGRLayer* generic = ds.GetLayerByName("Generic");
  if (generic == nullptr) return;
  generic->ResetReading();
  const OGRFeatureUniquePtr f(generic->GetNextFeature());
  if (!f) return;
  const int objl = f->GetFieldIndex("OBJL"), rcid = f->GetFieldIndex("RCID");
  throw InputError(shown_path + ": feature RCID " + (rcid >= 0 ? std::to_string(f->GetFieldAsInteger64(rcid)) : "?") +
                   ": expected an object class S-57 defines, got code " +
                   (objl >= 0 ? std::to_string(f->GetFieldAsInteger(objl)) : "?") +
                   " (a damaged cell, or one beyond S-57 edition 3.1)");
}

}  // namespace deepguide
