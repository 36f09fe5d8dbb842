# ev3lx-tasks.py — gdb commands for an EV3RT app running on ev3lx's host
# kernel (rtos_stub/src/host): `ev3lx-tasks` lists the RTOS's tasks with
# their priorities and states, read from the kernel's control blocks
# (tcb_table, runtsk: rtos_stub/src/host/kernel_impl.h), and what each
# waits for.  Load it with `gdb -x tools/gdb/ev3lx-tasks.py` or `source` it
# in a session (docs/ev3sim.md, "Debugging an app with gdb").
#
# It only reads memory: the program may be stopped anywhere (in a task, an
# interrupt, a device event), and listing the tasks changes nothing.

import gdb

# The kernel domain's ID (rtos_stub/include/kernel.h); an app's tasks are in a user domain.
TDOM_KERNEL = -1

# TOPPERS task states (rtos_stub/include/kernel.h: TTS_*).
TASK_STATES = {0x01: "running", 0x02: "ready", 0x04: "waiting", 0x08: "suspended",
               0x0c: "waiting-suspended", 0x10: "dormant"}

# What a waiting task waits for (struct tcb's wait: enum wait_kind), and the
# service call that makes it wait.
WAITS = {"WAIT_SLP": "wake-up (slp_tsk)", "WAIT_DLY": "delay (dly_tsk)",
         "WAIT_SEM": "semaphore %d", "WAIT_FLG": "eventflag %d",
         "WAIT_SDTQ": "data queue %d (send)", "WAIT_RDTQ": "data queue %d (receive)",
         "WAIT_SPDQ": "priority data queue %d (send)",
         "WAIT_RPDQ": "priority data queue %d (receive)", "WAIT_MTX": "mutex %d"}


def c_string(value):
    """The C string value points to, or '?' for a null pointer."""
    if int(value) == 0:
        return "?"
    return value.string()


def task_rows():
    """One (id, name, domain, priority, state, waits) tuple per configured task."""
    table = gdb.parse_and_eval("tcb_table")
    running = int(gdb.parse_and_eval("runtsk"))
    count = table.type.range()[1]
    rows = []
    for tskid in range(1, count + 1):
        tcb = table[tskid]
        if int(tcb) == 0:
            continue
        tcb = tcb.dereference()
        state = int(tcb["state"])
        name = TASK_STATES.get(state, "state 0x%x" % state)
        if state == 0x04 and bool(tcb["suspended"]):
            name = TASK_STATES[0x0c]
        if state == 0x02 and int(tcb.address) == running:
            name = TASK_STATES[0x01]
        waits = ""
        if state == 0x04:
            kind = str(tcb["wait"])
            waits = WAITS.get(kind, kind)
            if "%d" in waits:
                waits = waits % int(tcb["wobjid"])
            if int(tcb["tmevt"]["heap_index"]) != 0xffffffff:
                waits += ", with a timeout"
        domain = "kernel" if int(tcb["cfg"]["domid"]) == TDOM_KERNEL else "app"
        rows.append((tskid, c_string(tcb["cfg"]["name"]), domain, int(tcb["bpri"]), name, waits))
    return rows


class Ev3lxTasks(gdb.Command):
    """List the RTOS's tasks: ID, name, domain (app or kernel), current priority, state
and what a waiting task waits for."""

    def __init__(self):
        super().__init__("ev3lx-tasks", gdb.COMMAND_DATA)

    def invoke(self, argument, from_tty):
        if gdb.selected_inferior().pid == 0:
            raise gdb.GdbError("ev3lx-tasks: the program is not running; "
                               "run it and stop it (a breakpoint, Ctrl-C) first")
        try:
            rows = task_rows()
        except gdb.error as e:
            raise gdb.GdbError("ev3lx-tasks: cannot read the kernel's tasks (%s); "
                               "is this an ev3lx program?" % e)
        now = int(gdb.parse_and_eval("now_ns"))
        gdb.write("ev3lx tasks at %d.%06d ms of virtual time\n" % (now // 1000000, now % 1000000))
        gdb.write("%3s  %-24s %-6s %4s  %-18s %s\n" % ("ID", "NAME", "DOMAIN", "PRI", "STATE", "WAITS FOR"))
        for tskid, name, domain, pri, state, waits in rows:
            gdb.write(("%3d  %-24s %-6s %4d  %-18s %s" % (tskid, name, domain, pri, state, waits)).rstrip() + "\n")


Ev3lxTasks()
