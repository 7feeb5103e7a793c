#include "model/controls.hpp"

namespace mcdyna::model {

const char* ascii_database_name(AsciiDatabase d) {
  switch (d) {
    case AsciiDatabase::glstat:
      return "glstat";
    case AsciiDatabase::matsum:
      return "matsum";
    case AsciiDatabase::rcforc:
      return "rcforc";
    case AsciiDatabase::nodout:
      return "nodout";
    case AsciiDatabase::spcforc:
      return "spcforc";
    case AsciiDatabase::bndout:
      return "bndout";
    case AsciiDatabase::rwforc:
      return "rwforc";
  }
  return "?";
}

}  // namespace mcdyna::model
