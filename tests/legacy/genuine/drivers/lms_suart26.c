/*
 * lms_suart26 — a conformance module written as a Linux 2.6.33 DaVinci
 * (AM1808) driver of TI's PRU soft UART was: a platform driver for the
 * board's "ti_omapl_pru_suart" device (<linux/ti_omapl_pru_suart.h>: PRU
 * subsystem, McASP, PSC0, PSC1 and shared RAM as its five memory resources,
 * PRU_EVTOUT0 as its IRQ), its firmware from request_firmware, its clocks by
 * name, its serial port a struct uart_port whose uart_ops the module calls
 * itself (no tty layer, as LEGO's d_uart does), its port lock a 2.6
 * semaphore (init_MUTEX, down_trylock, up), and the PRU reached through
 * plain pointers: the channel registers in PRU data RAM, the PRU INTC, the
 * McASP clock dividers and serializers, the PSC modules, as TI's soft-UART
 * HAL programs them — the data RAM cleared with word stores at every byte
 * offset (unaligned), the system events raised and acknowledged by index.
 *
 * It drives soft UART 1 (channel 0 transmits on McASP serializer 3,
 * channel 1 receives on serializer 1: input port 4 of the EV3), with the
 * port's TX buffer enabled through a GPIO (BufferPin, bank * 16 + bit).
 * Received bytes arrive through the firmware's double FIFO in shared RAM:
 * an interrupt at each full half, and a time-out one for a partial half.
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <linux/slab.h>
#include <linux/serial.h>
#include <linux/serial_core.h>
#include <linux/platform_device.h>
#include <linux/firmware.h>
#include <linux/clk.h>
#include <linux/ti_omapl_pru_suart.h>
#include <mach/da8xx.h>
#include <asm/gpio.h>

#define   MODULE_NAME         "lms_suart26"
#define   DRV_NAME            "ti_omapl_pru_suart"
#define   FIRMWARE_NAME       "PRU_SUART.bin"

static int BufferPin = 7 * 16 + 10;     /* GP7[10]: port 4's TX buffer, low = on */
module_param(BufferPin, int, 0);

/* PRU subsystem (offsets in its 64 KiB) */
#define   PRU_DRAM0           0x0000
#define   PRU_INTC_GER        0x4010
#define   PRU_INTC_SISR       0x4020
#define   PRU_INTC_SICR       0x4024
#define   PRU_INTC_EISR       0x4028
#define   PRU_INTC_HIEISR     0x4034
#define   PRU_INTC_HIDISR     0x4038
#define   PRU_INTC_SECR1      0x4284
#define   PRU_INTC_CMR(n)     (0x4400 + 4 * (n))
#define   PRU_INTC_HMR(n)     (0x4800 + 4 * (n))
#define   PRU0_CONTROL        0x7000
#define   PRU0_IRAM           0x8000

/* PSC (PTCMD, PTSTAT, MDSTATn, MDCTLn) and the modules */
#define   PSC_PTCMD           0x120
#define   PSC_PTSTAT          0x128
#define   PSC_MDSTAT(n)       (0x800 + 4 * (n))
#define   PSC_MDCTL(n)        (0xA00 + 4 * (n))
#define   PSC0_PRU            13
#define   PSC1_MCASP0         7

/* McASP */
#define   MCASP_PFUNC         0x10
#define   MCASP_PDIR          0x14
#define   MCASP_GBLCTL        0x44
#define   MCASP_RFMT          0x68
#define   MCASP_ACLKRCTL      0x70
#define   MCASP_AHCLKRCTL     0x74
#define   MCASP_ACLKXCTL      0xB0
#define   MCASP_AHCLKXCTL     0xB4
#define   MCASP_SRCTL(n)      (0x180 + 4 * (n))

/* The firmware's channel registers and globals in data RAM 0 */
#define   CH_CTRL             0x0
#define   CH_CONFIG1          0x2
#define   CH_CONFIG2          0x4
#define   CH_STATUS           0x6
#define   CH_ACTIVE           0x7
#define   CH_DATA             0x8
#define   CH_BYTES_DONE       0xC
#define   GBL_IMR             0x80
#define   GBL_ISR             0x82
#define   GBL_PRU_ID          0x84
#define   GBL_MODE            0x85
#define   GBL_DELAY           0x86
#define   GBL_TIMEOUT         0x88

#define   TX_CH               0
#define   RX_CH               1
#define   TX_SER              3
#define   RX_SER              1
#define   FIFO_LEN            16
#define   DEFAULT_BAUD        115200    /* the McASP's bit clock; a channel divides it */
#define   ST_READY            0x01
#define   ST_COMPLETE         0x02
#define   ST_ERRORS           0x3C
#define   ST_TIMEOUT          0x40
#define   IE_TIMEOUT          (1 << 14)
#define   EVT_ARM_TO_PRU      32
#define   EVT_TX              (34 + TX_CH)
#define   EVT_RX              (34 + RX_CH)

#define   RING_SIZE           1024

static struct platform_device *SuartDev;
static void __iomem *PruBase;
static void __iomem *McaspBase;
static void __iomem *Psc0Base;
static void __iomem *Psc1Base;
static unsigned char *FifoVirt;
static unsigned long FifoPhys;
static const struct firmware *Firmware;
static struct clk *PruClk;
static struct clk *McaspClk;
static struct semaphore TxSem;
static struct uart_port SuartPort;
static struct circ_buf RxRing, TxRing;
static char RxData[RING_SIZE], TxData[RING_SIZE];

int       SuartIrqs;
int       SuartTimeouts;
int       SuartHalves;

/* ---- the HAL's register access, as TI writes it: plain pointers ---- */

static void PruWrite32(unsigned int Offset, unsigned int Value)
{
  *(volatile unsigned int *)((char *)PruBase + Offset) = Value;
}

static unsigned int PruRead32(unsigned int Offset)
{
  return *(volatile unsigned int *)((char *)PruBase + Offset);
}

/* Data RAM copies are byte by byte, as pru_ram_write_data does. */
static void PruRamWrite(unsigned int Offset, const void *pData, int Bytes)
{
  volatile unsigned char *pTo = (volatile unsigned char *)PruBase + Offset;
  const unsigned char *pFrom = pData;

  while (Bytes-- > 0)
    *pTo++ = *pFrom++;
}

static void PruRamRead(unsigned int Offset, void *pData, int Bytes)
{
  volatile unsigned char *pFrom = (volatile unsigned char *)PruBase + Offset;
  unsigned char *pTo = pData;

  while (Bytes-- > 0)
    *pTo++ = *pFrom++;
}

static u16 ChRead16(int Ch, int Reg)
{
  u16 Value = 0;

  PruRamRead(PRU_DRAM0 + 16 * Ch + Reg, &Value, 2);
  return Value;
}

static void ChWrite16(int Ch, int Reg, u16 Value)
{
  PruRamWrite(PRU_DRAM0 + 16 * Ch + Reg, &Value, 2);
}

static u8 ChRead8(int Ch, int Reg)
{
  u8 Value = 0;

  PruRamRead(PRU_DRAM0 + 16 * Ch + Reg, &Value, 1);
  return Value;
}

static void ChWrite8(int Ch, int Reg, u8 Value)
{
  PruRamWrite(PRU_DRAM0 + 16 * Ch + Reg, &Value, 1);
}

static void McaspWrite(unsigned int Offset, unsigned int Value)
{
  *(volatile unsigned int *)((char *)McaspBase + Offset) = Value;
}

/* A PSC module to Enable (3), as pru_psc_enable does: wait, NEXT, GO, wait. */
static void PscEnable(void __iomem *Psc, int Module)
{
  volatile unsigned int *pPsc = Psc;

  while (pPsc[PSC_PTSTAT / 4] & 1)
    ;
  if ((pPsc[PSC_MDSTAT(Module) / 4] & 0x3F) == 3)
    return;
  pPsc[PSC_MDCTL(Module) / 4] = (pPsc[PSC_MDCTL(Module) / 4] & ~0x1F) | 3;
  pPsc[PSC_PTCMD / 4] = 1;
  while (pPsc[PSC_PTSTAT / 4] & 1)
    ;
  while ((pPsc[PSC_MDSTAT(Module) / 4] & 0x3F) != 3)
    ;
}

/* The ARM's request to the PRU: system event 32 by index. */
static void ArmToPru(void)
{
  PruWrite32(PRU_INTC_SISR, EVT_ARM_TO_PRU);
}

/* ---- the soft UART ---- */

/* Receive request: FIFO_LEN bytes a half into the shared RAM, time-out on. */
static void RxRequest(void)
{
  u32 Phys = FifoPhys + 2 * FIFO_LEN;
  u16 Ctrl;

  ChWrite16(RX_CH, CH_CONFIG2, (ChRead16(RX_CH, CH_CONFIG2) & ~0x0F00) | ((FIFO_LEN - 1) << 8));
  PruRamWrite(PRU_DRAM0 + 16 * RX_CH + CH_DATA, &Phys, 4);
  Ctrl = ChRead16(RX_CH, CH_CTRL) & ~0x7;
  ChWrite16(RX_CH, CH_CTRL, Ctrl | 0x2 | 0x4);
  ChWrite16(RX_CH, CH_CONFIG1, ChRead16(RX_CH, CH_CONFIG1) | IE_TIMEOUT);
  ArmToPru();
}

/* Sends what the TX ring holds, up to FIFO_LEN bytes, from the shared RAM. */
static void TxChars(void)
{
  int Count = 0;
  u32 Phys = FifoPhys;
  u16 Ctrl;

  if (down_trylock(&TxSem))
    return;
  while (Count < FIFO_LEN && !uart_circ_empty(&TxRing))
  {
    FifoVirt[Count++] = TxRing.buf[TxRing.tail];
    TxRing.tail = (TxRing.tail + 1) & (RING_SIZE - 1);
    SuartPort.icount.tx++;
  }
  if (Count == 0)
  {
    up(&TxSem);
    return;
  }
  ChWrite16(TX_CH, CH_CONFIG2, (ChRead16(TX_CH, CH_CONFIG2) & ~0x0F00) | ((Count - 1) << 8));
  PruRamWrite(PRU_DRAM0 + 16 * TX_CH + CH_DATA, &Phys, 4);
  Ctrl = ChRead16(TX_CH, CH_CTRL) & ~0x7;
  ChWrite16(TX_CH, CH_CTRL, Ctrl | 0x1 | 0x4);
  ArmToPru();
}

/* The received half (or, after a time-out, the bytes so far) into the RX ring. */
static void RxChars(void)
{
  u8 Status = ChRead8(RX_CH, CH_STATUS);
  int Count = FIFO_LEN, First = 0, Index;

  if (Status & ST_TIMEOUT)
  {
    Count = ChRead8(RX_CH, CH_BYTES_DONE);
    if (Count > FIFO_LEN)
    {
      Count -= FIFO_LEN;
      First = FIFO_LEN;
    }
    SuartTimeouts++;
  }
  else
  {
    if (Status & ST_COMPLETE)
      First = FIFO_LEN;
    SuartHalves++;
  }
  if (Status & ST_ERRORS)
  {
    SuartPort.icount.brk++;
    Count = 0;
  }
  for (Index = 0; Index < Count; Index++)
  {
    if (CIRC_SPACE(RxRing.head, RxRing.tail, RING_SIZE) == 0)
    {
      SuartPort.icount.buf_overrun++;
      break;
    }
    RxRing.buf[RxRing.head] = FifoVirt[2 * FIFO_LEN + First + Index];
    RxRing.head = (RxRing.head + 1) & (RING_SIZE - 1);
    SuartPort.icount.rx++;
  }
  ChWrite8(RX_CH, CH_STATUS, Status & ~ST_ERRORS);
  if (Status & ST_TIMEOUT)
  {
    ChWrite8(RX_CH, CH_BYTES_DONE, 0);
    RxRequest();
  }
}

static irqreturn_t SuartInterrupt(int Irq, void *pDev)
{
  unsigned int Pending;
  u16 Isr;

  SuartIrqs++;
  spin_lock(&SuartPort.lock);
  Pending = PruRead32(PRU_INTC_SECR1);
  if (Pending & (1 << (EVT_RX - 32)))
  {
    PruWrite32(PRU_INTC_SICR, EVT_RX);
    RxChars();
  }
  if (Pending & (1 << (EVT_TX - 32)))
  {
    PruWrite32(PRU_INTC_SICR, EVT_TX);
    ChWrite8(TX_CH, CH_STATUS, ChRead8(TX_CH, CH_STATUS) & ~ST_COMPLETE);
    up(&TxSem);
    TxChars();
  }
  PruRamRead(PRU_DRAM0 + GBL_ISR, &Isr, 2);
  Isr &= ~((1 << TX_CH) | (1 << RX_CH));
  PruRamWrite(PRU_DRAM0 + GBL_ISR, &Isr, 2);
  spin_unlock(&SuartPort.lock);
  return (Pending & ((1 << (EVT_RX - 32)) | (1 << (EVT_TX - 32)))) ? IRQ_HANDLED : IRQ_NONE;
}

/* ---- uart_ops, called by the module itself ---- */

static unsigned int SuartTxEmpty(struct uart_port *pPort)
{
  return (ChRead8(TX_CH, CH_STATUS) & ST_READY) ? 0 : TIOCSER_TEMT;
}

static void SuartStartTx(struct uart_port *pPort)
{
  TxChars();
}

static int SuartStartup(struct uart_port *pPort)
{
  u16 Imr = (1 << TX_CH) | (1 << RX_CH);
  int Result;

  Result = request_irq(pPort->irq, SuartInterrupt, pPort->irqflags, "suart_irq", pPort);
  if (Result)
    return Result;
  PruRamWrite(PRU_DRAM0 + GBL_IMR, &Imr, 2);
  PruWrite32(PRU_INTC_EISR, EVT_TX);
  PruWrite32(PRU_INTC_EISR, EVT_RX);
  RxRequest();
  return 0;
}

static void SuartShutdown(struct uart_port *pPort)
{
  u16 Imr = 0;

  PruRamWrite(PRU_DRAM0 + GBL_IMR, &Imr, 2);
  free_irq(pPort->irq, pPort);
}

/* Baud: the channels' prescaler of the McASP's DEFAULT_BAUD bit clock. */
static void SuartSetTermios(struct uart_port *pPort, struct ktermios *pNew, struct ktermios *pOld)
{
  unsigned int Baud = pNew->c_ospeed ? pNew->c_ospeed : 2400;
  u16 Divisor = DEFAULT_BAUD / Baud;

  ChWrite16(TX_CH, CH_CONFIG1, (ChRead16(TX_CH, CH_CONFIG1) & ~0x3FF) | Divisor);
  ChWrite16(RX_CH, CH_CONFIG1, (ChRead16(RX_CH, CH_CONFIG1) & ~0x3FF) | Divisor);
  uart_update_timeout(pPort, pNew->c_cflag, Baud);
}

static const struct uart_ops SuartOps = {
  .tx_empty     = SuartTxEmpty,
  .start_tx     = SuartStartTx,
  .startup      = SuartStartup,
  .shutdown     = SuartShutdown,
  .set_termios  = SuartSetTermios,
};

/* ---- the PRU, as pru_softuart_init brings it up ---- */

static void PruInit(const unsigned char *pCode, size_t Size)
{
  unsigned int Loop;
  u16 Value;

  PscEnable(Psc1Base, PSC1_MCASP0);
  McaspWrite(MCASP_GBLCTL, 0);
  McaspWrite(MCASP_RFMT, 0x0000A038);                 /* 8-bit slots: 8 samples a bit */
  McaspWrite(MCASP_ACLKRCTL, 0x000000A0);
  McaspWrite(MCASP_AHCLKRCTL, 0x00008000 | (26 - 1)); /* 24 MHz / 26: 8 x 115200 */
  McaspWrite(MCASP_ACLKXCTL, 0x000000E0);
  McaspWrite(MCASP_AHCLKXCTL, 0x00008000 | 208);
  for (Loop = 0; Loop < 16; Loop++)
    McaspWrite(MCASP_SRCTL(Loop), 0x000C);
  McaspWrite(MCASP_PFUNC, 1 << TX_SER);
  McaspWrite(MCASP_PDIR, 1 << TX_SER);

  PscEnable(Psc0Base, PSC0_PRU);
  PruWrite32(PRU0_CONTROL, 0);
  for (Loop = 0; Loop < 512; Loop++)
    *(volatile unsigned int *)((char *)PruBase + PRU_DRAM0 + Loop) = 0x0;
  for (Loop = 0; Loop < Size / 4; Loop++)
    ((volatile unsigned int *)((char *)PruBase + PRU0_IRAM))[Loop] = ((const unsigned int *)pCode)[Loop];

  for (Loop = 0; Loop <= 9; Loop++)
    PruWrite32(PRU_INTC_HIDISR, Loop);
  PruWrite32(PRU_INTC_GER, 1);
  PruWrite32(PRU_INTC_HMR(0), 0x03020100);
  PruWrite32(PRU_INTC_HMR(1), 0x07060504);
  PruWrite32(PRU_INTC_HMR(2), 0x00000908);
  PruWrite32(PRU_INTC_CMR(8), 0x02020100);            /* events 32, 33 to the PRU; 34, 35 to channel 2 */
  for (Loop = 0; Loop < 18; Loop++)
    PruWrite32(PRU_INTC_SICR, 32 + Loop);
  PruWrite32(PRU_INTC_EISR, 32);
  for (Loop = 0; Loop <= 9; Loop++)
    PruWrite32(PRU_INTC_HIEISR, Loop);

  Value = 0;
  PruRamWrite(PRU_DRAM0 + GBL_PRU_ID, &Value, 1);
  Value = 3;                                          /* RX and TX on this PRU */
  PruRamWrite(PRU_DRAM0 + GBL_MODE, &Value, 1);
  Value = 3;
  PruRamWrite(PRU_DRAM0 + GBL_DELAY, &Value, 1);
  Value = DEFAULT_BAUD * 10 / 1000;                   /* 10 ms of idle receive frames */
  PruRamWrite(PRU_DRAM0 + GBL_TIMEOUT, &Value, 2);

  ChWrite16(TX_CH, CH_CTRL, (TX_SER << 8) | 0x1);
  ChWrite16(TX_CH, CH_CONFIG1, (1 << 10) | 1);
  ChWrite16(TX_CH, CH_CONFIG2, 10);                   /* start, 8 data, stop */
  ChWrite8(TX_CH, CH_ACTIVE, 0x80);
  ChWrite16(RX_CH, CH_CTRL, (RX_SER << 8) | 0x2);
  ChWrite16(RX_CH, CH_CONFIG1, (1 << 10) | 1);
  ChWrite16(RX_CH, CH_CONFIG2, 10);
  ChWrite8(RX_CH, CH_ACTIVE, 0x80);
  McaspWrite(MCASP_SRCTL(RX_SER), 0x000E);

  PruWrite32(PRU0_CONTROL, 0x8 | 0x2);               /* COUNTENABLE, ENABLE */
}

static int __devinit SuartProbe(struct platform_device *pDev)
{
  struct resource *pRes[5];
  int Index, Result;

  if (pDev->dev.platform_data == NULL)
    return (-ENODEV);
  for (Index = 0; Index < 5; Index++)
  {
    pRes[Index] = platform_get_resource(pDev, IORESOURCE_MEM, Index);
    if (pRes[Index] == NULL)
      return (-ENODEV);
  }
  PruBase = ioremap(pRes[0]->start, resource_size(pRes[0]));
  McaspBase = ioremap(pRes[1]->start, resource_size(pRes[1]));
  Psc0Base = ioremap(pRes[2]->start, resource_size(pRes[2]));
  Psc1Base = ioremap(pRes[3]->start, resource_size(pRes[3]));
  FifoVirt = ioremap(pRes[4]->start, resource_size(pRes[4]));
  FifoPhys = pRes[4]->start;
  if (!PruBase || !McaspBase || !Psc0Base || !Psc1Base || !FifoVirt)
    return (-ENOMEM);

  PruClk = clk_get(&pDev->dev, "pru_ck");
  McaspClk = clk_get(NULL, "mcasp_pru");
  if (IS_ERR(PruClk) || IS_ERR(McaspClk))
    return (-ENODEV);
  clk_enable(McaspClk);
  clk_enable(PruClk);
  Result = request_firmware(&Firmware, FIRMWARE_NAME, &pDev->dev);
  if (Result)
  {
    clk_disable(PruClk);
    clk_disable(McaspClk);
    return (-ENODEV);
  }
  PruInit(Firmware->data, Firmware->size);

  SuartPort.iotype = UPIO_MEM;
  SuartPort.flags = UPF_BOOT_AUTOCONF | UPF_IOREMAP;
  SuartPort.mapbase = pRes[1]->start;
  SuartPort.type = OMAPL_PRU_SUART;
  SuartPort.irq = platform_get_irq(pDev, 0);
  SuartPort.irqflags = IRQF_SHARED;
  SuartPort.uartclk = clk_get_rate(McaspClk);
  SuartPort.fifosize = FIFO_LEN;
  SuartPort.ops = &SuartOps;
  SuartPort.dev = &pDev->dev;
  spin_lock_init(&SuartPort.lock);
  init_MUTEX(&TxSem);
  SuartDev = pDev;
  return 0;
}

static int __devexit SuartRemove(struct platform_device *pDev)
{
  PruWrite32(PRU0_CONTROL, 0);
  release_firmware(Firmware);
  clk_disable(PruClk);
  clk_disable(McaspClk);
  clk_put(PruClk);
  clk_put(McaspClk);
  iounmap(FifoVirt);
  iounmap(Psc1Base);
  iounmap(Psc0Base);
  iounmap(McaspBase);
  iounmap(PruBase);
  SuartDev = NULL;
  return 0;
}

static struct platform_driver SuartDriver = {
  .probe    = SuartProbe,
  .remove   = __devexit_p(SuartRemove),
  .suspend  = NULL,
  .resume   = NULL,
  .driver   = {
    .name   = DRV_NAME,
    .owner  = THIS_MODULE,
  },
};

/* ---- what the rest of the driver calls ---- */

void      SuartSetBaud(unsigned int Baud)
{
  struct ktermios Config;

  memset(&Config, 0, sizeof(Config));
  Config.c_cflag = CS8 | CREAD;
  Config.c_ospeed = Baud;
  SuartPort.ops->set_termios(&SuartPort, &Config, NULL);
}

int       SuartWrite(const unsigned char *pData, int Size)
{
  int Index;

  for (Index = 0; Index < Size && CIRC_SPACE(TxRing.head, TxRing.tail, RING_SIZE); Index++)
  {
    TxRing.buf[TxRing.head] = pData[Index];
    TxRing.head = (TxRing.head + 1) & (RING_SIZE - 1);
  }
  SuartPort.ops->start_tx(&SuartPort);
  return Index;
}

int       SuartRead(unsigned char *pData, int Size)
{
  int Index;

  for (Index = 0; Index < Size && CIRC_CNT(RxRing.head, RxRing.tail, RING_SIZE); Index++)
  {
    pData[Index] = RxRing.buf[RxRing.tail];
    RxRing.tail = (RxRing.tail + 1) & (RING_SIZE - 1);
  }
  return Index;
}

unsigned int SuartTimeout(void)
{
  return SuartPort.timeout;
}

unsigned int SuartTxIdle(void)
{
  return SuartPort.ops->tx_empty(&SuartPort);
}

static int __init ModuleInit(void)
{
  int     Result;

  RxRing.buf = RxData;
  TxRing.buf = TxData;
  RxRing.head = RxRing.tail = TxRing.head = TxRing.tail = 0;
  if (!gpio_is_valid(BufferPin))
    return (-EINVAL);
  Result = gpio_request(BufferPin, MODULE_NAME);
  if (Result)
    return Result;
  gpio_direction_output(BufferPin, 0);
  Result = platform_driver_register(&SuartDriver);
  if (Result == 0 && SuartDev == NULL)
  {
    platform_driver_unregister(&SuartDriver);
    Result = -ENODEV;
  }
  if (Result == 0)
  {
    SuartSetBaud(2400);
    Result = SuartPort.ops->startup(&SuartPort);
    if (Result)
      platform_driver_unregister(&SuartDriver);
  }
  if (Result)
    gpio_free(BufferPin);
  else
    printk(KERN_INFO "%s: soft UART 1 on IRQ %u, PRU at %lu Hz\n", MODULE_NAME, SuartPort.irq, clk_get_rate(PruClk));
  return Result;
}

static void __exit ModuleExit(void)
{
  SuartPort.ops->shutdown(&SuartPort);
  platform_driver_unregister(&SuartDriver);
  gpio_direction_input(BufferPin);
  gpio_free(BufferPin);
}

MODULE_LICENSE("GPL");
module_init(ModuleInit);
module_exit(ModuleExit);
