##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

import sigrokdecode as srd
from .regmap import CHIPS, REGISTERS, STATUS_BITS

ANN_DATAGRAM, ANN_FIELD, ANN_STATUS, ANN_STATUS_BIT, ANN_WARNING = range(5)


def lookup(chip, a7):
    '''(register, motor) at a 7-bit address, or None where the chip has none (TMC428 §7.1).'''
    bit = CHIPS[chip]
    if a7 & 0x40:
        space, index, motor = 'ram', (a7 & 0x3F) >> 5, None
    elif a7 >> 4 == 3:
        space, index, motor = 'global', a7 & 0xF, None
    else:
        space, index, motor = 'motor', a7 & 0xF, a7 >> 4
        if chip == 'tmc4210' and motor != 0:
            return None
    for r in REGISTERS:
        if r[1] == space and r[2] == index and r[3] & bit:
            return r, motor
    return None


def display_name(chip, a7):
    '''x_target[1] for motor registers, ram[12] for RAM words, unused[...] elsewhere.'''
    found = lookup(chip, a7)
    if found is None:
        if a7 & 0x40:
            return 'unused[ram%d]' % (a7 & 0x3F)
        if a7 >> 4 == 3:
            return 'unused[g%d]' % (a7 & 0xF)
        return 'unused[m%d.%d]' % (a7 >> 4, a7 & 0xF)
    reg, motor = found
    if motor is not None:
        return '%s[%d]' % (reg[0], motor)
    if reg[1] == 'ram':
        return 'ram[%d]' % (a7 & 0x3F)
    return reg[0]


def field_value(field, word):
    _, lsb, width, signed, _ = field
    raw = (word >> lsb) & ((1 << width) - 1)
    if signed and raw >> (width - 1):
        raw -= 1 << width
    return raw


def field_text(field, word):
    v = field_value(field, word)
    if field[2] >= 8 and not field[3]:
        return '%s=%d ($%X)' % (field[0], v, v)
    return '%s=%d' % (field[0], v)


def data_fields(chip, a7, data):
    '''[(text, msb, lsb)] of a data word: the register's fields, or a RAM word's two cells.'''
    found = lookup(chip, a7)
    if found is None:
        return []
    reg = found[0]
    if reg[1] == 'ram':
        a = a7 & 0x3F
        return [('cell%d=%d' % (2 * a + 1, (data >> 8) & 63), 13, 8),
                ('cell%d=%d' % (2 * a, data & 63), 5, 0)]
    return [(field_text(f, data), f[1] + f[2] - 1, f[1]) for f in reg[5]]


def status_text(st):
    names = [STATUS_BITS[b] for b in range(7, -1, -1) if st >> b & 1]
    return 'status $%02X: %s' % (st, ' '.join(names) if names else '-')


def decode(chip, datagram, reply):
    '''The line `tmc429 spi --decode` prints for a datagram and its reply.'''
    a7 = (datagram >> 25) & 0x7F
    read = (datagram >> 24) & 1
    data = reply & 0xFFFFFF if read else datagram & 0xFFFFFF
    fields = ' '.join(t for t, _, _ in data_fields(chip, a7, data))
    return '%s %s%s%s | %s' % ('R' if read else 'W', display_name(chip, a7),
                               ' ' if fields else '', fields, status_text(reply >> 24))


class Decoder(srd.Decoder):
    api_version = 3
    id = 'tmc429'
    name = 'TMC429'
    longname = 'Trinamic TMC428/TMC429/TMC4210'
    desc = 'Stepper motor motion controller: registers over its µC SPI port.'
    license = 'mit'
    inputs = ['spi']
    outputs = []
    tags = ['Embedded/industrial']
    options = (
        {'id': 'chip', 'desc': 'Chip', 'default': 'tmc429',
         'values': ('tmc428', 'tmc429', 'tmc4210')},
    )
    annotations = (
        ('datagram', 'Datagram'),
        ('field', 'Field'),
        ('status', 'Status byte'),
        ('status-bit', 'Status bit'),
        ('warning', 'Warning'),
    )
    annotation_rows = (
        ('datagrams', 'Datagrams', (ANN_DATAGRAM,)),
        ('fields', 'Fields', (ANN_FIELD,)),
        ('status', 'Status', (ANN_STATUS, ANN_STATUS_BIT)),
        ('warnings', 'Warnings', (ANN_WARNING,)),
    )

    def __init__(self):
        self.reset()

    def reset(self):
        self.mosi = []
        self.miso = []
        self.active = False
        self.have_cs = True
        self.ss_frame = 0

    def start(self):
        self.out_ann = self.register(srd.OUTPUT_ANN)

    def put_ann(self, ss, es, ann, texts):
        self.put(ss, es, self.out_ann, [ann, texts])

    def frame_end(self, es):
        n = len(self.mosi)
        if n == 0:
            return
        chip = self.options['chip']
        mosi = miso = 0
        for b in self.mosi:
            mosi = mosi << 1 | b[0]
        for b in self.miso:
            miso = miso << 1 | b[0]
        bits = self.miso if self.miso else self.mosi
        ss, end = self.ss_frame, es
        if len(self.miso) >= 8:
            st = miso >> (len(self.miso) - 8)
            self.put_ann(bits[0][1], bits[7][2], ANN_STATUS, [status_text(st), '$%02X' % st])
            for b in range(8):
                if st >> (7 - b) & 1:
                    self.put_ann(bits[b][1], bits[b][2], ANN_STATUS_BIT, [STATUS_BITS[7 - b]])
        if n == 32 and len(self.miso) in (0, 32):
            text = decode(chip, mosi, miso if self.miso else 0)
            a7 = (mosi >> 25) & 0x7F
            head = text.split(' | ')[0]
            self.put_ann(ss, end, ANN_DATAGRAM, [text, head, head.split(' ')[0] + ' ' + display_name(chip, a7)])
            read = (mosi >> 24) & 1
            data = (miso if read else mosi) & 0xFFFFFF
            src = self.miso if read and self.miso else self.mosi
            for t, msb, lsb in data_fields(chip, a7, data):
                self.put_ann(src[31 - msb][1], src[31 - lsb][2], ANN_FIELD, [t])
            if lookup(chip, a7) is None:
                self.put_ann(ss, end, ANN_WARNING, ['no register at A7 $%02X on the %s' % (a7, chip.upper())])
        else:
            text = 'short frame, nothing executed' if n < 32 else '%d-bit frame, nothing executed' % n
            if len(self.miso) >= 8:
                text += ' | ' + status_text(miso >> (len(self.miso) - 8))
            self.put_ann(ss, end, ANN_DATAGRAM, [text, '%d bits' % n])

    def decode(self, ss, es, data):
        ptype, d1, d2 = data
        if ptype == 'CS-CHANGE':
            if d1 is None and d2 is None:
                self.have_cs = False
                return
            if d2 == 0:
                self.active = True
                self.ss_frame = ss
                self.mosi, self.miso = [], []
            elif d1 == 0 and d2 == 1:
                self.active = False
                self.frame_end(es)
                self.mosi, self.miso = [], []
        elif ptype == 'BITS':
            if not self.active and self.have_cs:
                return
            if not self.mosi and not self.have_cs:
                self.ss_frame = ss
            if d1 is not None:
                self.mosi.extend(reversed(d1))
            if d2 is not None:
                self.miso.extend(reversed(d2))
            if not self.have_cs and len(self.mosi) == 32:
                self.frame_end(es)
                self.mosi, self.miso = [], []
