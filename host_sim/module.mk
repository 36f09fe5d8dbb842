# host_sim: the simulated AM1808 and EV3 devices (host configurations only;
# nothing here goes into the AM1808 target library).
#   include/host_sim/          core API: regs, board, gpio, intc, psc, syscfg, clock, trace, scenario
#   include/host_sim/devices/  device models (eHRPWM/eCAP, SPI0/1 + ADC + display, UARTs, motors, sensors)
# Layers, each using only those above it in this list (make layer-check):
#   src/core/                  the simulator: register space, trapping, virtual clock, traces, random streams
#   src/soc/                   the AM1808: its peripherals (AINTC, GPIO, PSC, SYSCFG, PLLC, TIMER64P3,
#                              eHRPWM, eCAP, SPI0/SPI1, UARTs, I2C0/I2C1) and the board assembly (hs_board_init)
#   src/ev3/                   the EV3 board (ports, motors, sensors, LUMP, buttons/LEDs, ADC, battery, display),
#                              connected to the SoC's outputs as peers
#   src/harness/               scenarios and scripts: boot the board and the RTOS, run, inject
#   src/bench/                 the full-brick speed run
HOST_SRCS += $(sort $(foreach d,core soc ev3 harness bench,$(wildcard host_sim/src/$(d)/*.c)))
