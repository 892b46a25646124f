#include "board_factory.hpp"

#ifdef SW8085_HAVE_BOARD
#include "board_machine.hpp"
#endif

namespace contour::sw8085 {

i8085::MachineFactory board_factory() {
#ifdef SW8085_HAVE_BOARD
  return board8085::make_board_machine;
#else
  return {};
#endif
}

}  // namespace contour::sw8085
