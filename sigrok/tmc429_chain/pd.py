##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

import sigrokdecode as srd

ANN_BIT, ANN_RBIT, ANN_GROUP, ANN_RGROUP, ANN_DATAGRAM, ANN_READBACK, ANN_COVER, ANN_WARNING = range(8)

# TMC236/TMC239/TMC246/TMC249: the 12 bits of one driver in the order sent (TMC428 Table 11-2,
# column "TMC23x / TMC24x Bit Name").
TMC23X_BITS = ('MDA', 'CA3', 'CA2', 'CA1', 'CA0', 'PHA', 'MDB', 'CB3', 'CB2', 'CB1', 'CB0', 'PHB')
# TMC246/TMC249 status bits in the order received, bit 11 first (TMC429 Figure 8.5).
TMC246_STATUS = ('LD2', 'LD1', 'LD0', '1', 'OT', 'OTPW', 'UV', 'OCHS', 'OLB', 'OLA', 'OCB', 'OCA')

# TMC26x in SPI mode: 20-bit datagrams, register by the address bits 19..17 (TMC260/TMC261/
# TMC262 datasheets, SPI interface); fields (name, msb, lsb).
TMC26X_REGS = (
    ('DRVCTRL', 0b000, 0b100, (('PHA', 17, 17), ('CA', 16, 9), ('PHB', 8, 8), ('CB', 7, 0))),
    ('CHOPCONF', 0b100, 0b111, (('TBL', 16, 15), ('CHM', 14, 14), ('RNDTF', 13, 13), ('HDEC', 12, 11),
                                ('HEND', 10, 7), ('HSTRT', 6, 4), ('TOFF', 3, 0))),
    ('SMARTEN', 0b101, 0b111, (('SEIMIN', 15, 15), ('SEDN', 14, 13), ('SEMAX', 11, 8), ('SEUP', 6, 5),
                               ('SEMIN', 3, 0))),
    ('SGCSCONF', 0b110, 0b111, (('SFILT', 16, 16), ('SGT', 14, 8), ('CS', 4, 0))),
    ('DRVCONF', 0b111, 0b111, (('TST', 16, 16), ('SLPH', 15, 14), ('SLPL', 13, 12), ('DISS2G', 10, 10),
                               ('TS2G', 9, 8), ('SDOFF', 7, 7), ('VSENSE', 6, 6), ('RDSEL', 5, 4))),
)
# TMC26x response bits 7..0 (bits 19..10: microstep position or stallGuard value by RDSEL).
TMC26X_STATUS = ('STST', 'OLB', 'OLA', 'S2GB', 'S2GA', 'OTPW', 'OT', 'SG')


def value(bits):
    v = 0
    for b in bits:
        v = v << 1 | b
    return v


def hex_of(bits):
    return '$%0*X' % (max(1, (len(bits) + 3) // 4), value(bits))


def tmc23x_group(bits):
    named = dict(zip(TMC23X_BITS, bits))
    ca = value([named[n] for n in ('CA3', 'CA2', 'CA1', 'CA0')])
    cb = value([named[n] for n in ('CB3', 'CB2', 'CB1', 'CB0')])
    return 'MDA=%d CA=%d PHA=%d MDB=%d CB=%d PHB=%d' % (named['MDA'], ca, named['PHA'], named['MDB'], cb, named['PHB'])


def tmc246_status(bits):
    named = dict(zip(TMC246_STATUS, bits))
    ld = value([named['LD2'], named['LD1'], named['LD0']])
    flags = [n for n in TMC246_STATUS[4:] if named[n]]
    return 'LD=%d %s' % (ld, ' '.join(flags) if flags else '-')


def tmc26x_group(bits):
    v = value(bits)
    for name, code, mask, fields in TMC26X_REGS:
        if (v >> 17) & mask == code:
            return '%s %s' % (name, ' '.join('%s=%d' % (f, (v >> lsb) & ((1 << (msb - lsb + 1)) - 1)) for f, msb, lsb in fields))
    return hex_of(bits)


def tmc26x_status(bits):
    v = value(bits)
    flags = [n for i, n in enumerate(TMC26X_STATUS) if v >> (7 - i) & 1]
    return 'MSTEP/SG=%d %s' % (v >> 10, ' '.join(flags) if flags else '-')


DRIVERS = {
    # group length, bit names, group decoder, readback decoder
    'generic': (None, None, None, None),
    'tmc23x-24x': (12, TMC23X_BITS, tmc23x_group, tmc246_status),
    'tmc26x': (20, None, tmc26x_group, tmc26x_status),
}


class Decoder(srd.Decoder):
    api_version = 3
    id = 'tmc429_chain'
    name = 'TMC429 chain'
    longname = 'Trinamic TMC428/TMC429 driver chain'
    desc = 'Datagrams of the motion controller to its SPI stepper motor drivers.'
    license = 'mit'
    inputs = ['logic']
    outputs = []
    tags = ['Embedded/industrial']
    channels = (
        {'id': 'cs', 'name': 'nSCS_S', 'desc': 'Driver chain select'},
        {'id': 'clk', 'name': 'SCK_S', 'desc': 'Driver chain clock'},
        {'id': 'sdo', 'name': 'SDO_S', 'desc': 'Data to the drivers'},
    )
    optional_channels = (
        {'id': 'sdi', 'name': 'SDI_S', 'desc': 'Data from the drivers'},
    )
    options = (
        {'id': 'drivers', 'desc': 'Drivers', 'default': 'generic', 'values': tuple(DRIVERS)},
        {'id': 'cs_polarity', 'desc': 'nSCS_S polarity', 'default': 'active-low',
         'values': ('active-low', 'active-high')},
        {'id': 'clk_polarity', 'desc': 'SCK_S', 'default': 'normal', 'values': ('normal', 'inverted')},
        {'id': 'cover_pos', 'desc': 'Cover datagram position', 'default': 0},
        {'id': 'cover_len', 'desc': 'Cover datagram length (0: none)', 'default': 0},
    )
    annotations = (
        ('bit', 'Bit'),
        ('readback-bit', 'Readback bit'),
        ('group', 'NxM group'),
        ('readback-group', 'Readback group'),
        ('datagram', 'Datagram'),
        ('readback', 'Readback'),
        ('cover', 'Cover datagram'),
        ('warning', 'Warning'),
    )
    annotation_rows = (
        ('bits', 'Bits', (ANN_BIT,)),
        ('groups', 'Groups', (ANN_GROUP,)),
        ('datagrams', 'Datagrams', (ANN_DATAGRAM, ANN_COVER)),
        ('readback-bits', 'Readback bits', (ANN_RBIT,)),
        ('readback-groups', 'Readback groups', (ANN_RGROUP,)),
        ('readback', 'Readback', (ANN_READBACK,)),
        ('warnings', 'Warnings', (ANN_WARNING,)),
    )

    def __init__(self):
        self.reset()

    def reset(self):
        self.samplerate = None

    def start(self):
        self.out_ann = self.register(srd.OUTPUT_ANN)

    def metadata(self, key, value):
        if key == srd.SRD_CONF_SAMPLERATE:
            self.samplerate = value

    def ann(self, ss, es, a, texts):
        self.put(ss, es, self.out_ann, [a, texts])

    def groups(self, rises):
        '''Splits the bits at the NxM pauses: a gap between rising SCK_S edges of more than 1.5
        times the shortest one (TMC428 §9.7: the NxM gap is at least one SCK_S period).'''
        if len(rises) < 2:
            return [(0, len(rises))]
        period = min(b - a for a, b in zip(rises, rises[1:]))
        out, start = [], 0
        for i in range(1, len(rises)):
            if rises[i] - rises[i - 1] > 1.5 * period:
                out.append((start, i))
                start = i
        out.append((start, len(rises)))
        return out

    def datagram(self, ss, es, bits, rbits, rises, ends):
        n = len(bits)
        if n == 0:
            self.ann(ss, es, ANN_WARNING, ['chip select without SCK_S edges'])
            return
        glen, names, gdec, rdec = DRIVERS[self.options['drivers']]
        for i in range(n):
            name = names[i % len(names)] if names else str(i)
            self.ann(rises[i], ends[i], ANN_BIT, ['%s=%d' % (name, bits[i]), str(bits[i])])
            if rbits:
                self.ann(rises[i], ends[i], ANN_RBIT, [str(rbits[i])])
        self.ann(ss, es, ANN_DATAGRAM, ['%d bits %s' % (n, hex_of(bits)), hex_of(bits)])
        if rbits:
            self.ann(ss, es, ANN_READBACK, ['readback %d bits %s' % (n, hex_of(rbits)), hex_of(rbits)])
        for k, (a, b) in enumerate(self.groups(rises)):
            text = 'group %d: %d bits %s' % (k + 1, b - a, hex_of(bits[a:b]))
            if gdec and b - a == glen:
                text = 'motor %d: %s' % (k, gdec(bits[a:b]))
            elif gdec:
                self.ann(rises[a], ends[b - 1], ANN_WARNING, ['group of %d bits: the %s have %d' % (b - a, self.options['drivers'], glen)])
            self.ann(rises[a], ends[b - 1], ANN_GROUP, [text, hex_of(bits[a:b])])
            if rbits:
                rt = 'group %d: %s' % (k + 1, hex_of(rbits[a:b]))
                if rdec and b - a == glen:
                    rt = 'motor %d: %s' % (k, rdec(rbits[a:b]))
                self.ann(rises[a], ends[b - 1], ANN_RGROUP, [rt, hex_of(rbits[a:b])])
        pos, ln = self.options['cover_pos'], self.options['cover_len']
        if 0 < ln <= 24 and pos + ln <= n:
            cov = bits[pos:pos + ln]
            text = 'cover %d bits %s' % (ln, hex_of(cov))
            if self.options['drivers'] == 'tmc26x' and ln == 20:
                text += ': ' + tmc26x_group(cov)
            self.ann(rises[pos], ends[pos + ln - 1], ANN_COVER, [text])

    def decode(self):
        active = 0 if self.options['cs_polarity'] == 'active-low' else 1
        rising = 'r' if self.options['clk_polarity'] == 'normal' else 'f'
        # an unassigned channel reads 0xff (has_channel() of libsigrokdecode 0.5.3 miscounts
        # the references of the bools it returns)
        have_sdi = self.wait({})[3] in (0, 1)
        while True:
            cs, clk, sdo, sdi = self.wait({0: 'f' if active == 0 else 'r'})
            ss = self.samplenum
            bits, rbits, rises = [], [], []
            while True:
                cs, clk, sdo, sdi = self.wait([{0: 'e'}, {1: rising}])
                if self.matched[0]:
                    break
                bits.append(sdo)
                if have_sdi:
                    rbits.append(sdi)
                rises.append(self.samplenum)
            ends = rises[1:] + [self.samplenum]
            self.datagram(ss, self.samplenum, bits, rbits, rises, ends)
