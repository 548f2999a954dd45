// An XDMF file made ready for VTK's Xdmf3 reader. Its HDF5 files must be there (the HDF5 library
// prints its own error stack for a missing one, and the Xdmf library then fails on what it did
// not read). Floating-point DataItems that declare no Precision are 4-byte floats by XDMF's
// default, and the Xdmf library reads them so, though DOLFINx (before 0.6) writes 8-byte values
// under such items: the reader is given a temporary copy that declares them 8 bytes wide (HDF5
// converts a dataset of 4-byte floats to doubles exactly, so the copy loses nothing either way),
// with the heavy data's file names made absolute.
#pragma once

#include <string>

namespace hoct {

class XdmfForReading {
public:
  // Throws InputError for a file that is not XML or whose HDF5 file is missing.
  explicit XdmfForReading(const std::string &path);
  ~XdmfForReading(); // removes the copy
  XdmfForReading(const XdmfForReading &) = delete;
  XdmfForReading &operator=(const XdmfForReading &) = delete;

  // The file to give the reader: an absolute path, to the copy if one was made.
  const std::string &path() const { return path_; }
  // The DataItems whose Precision the copy declares.
  int widened() const { return widened_; }

private:
  std::string path_;
  bool copy_ = false;
  int widened_ = 0;
};

} // namespace hoct
