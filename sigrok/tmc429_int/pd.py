##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

import sigrokdecode as srd

ANN_EDGE, ANN_ACTIVE = range(2)


class Decoder(srd.Decoder):
    api_version = 3
    id = 'tmc429_int'
    name = 'TMC429 nINT'
    longname = 'Trinamic TMC428/TMC429/TMC4210 interrupt'
    desc = 'nINT outside the µC frames of nINT_SDO_C.'
    license = 'mit'
    inputs = ['logic']
    outputs = []
    tags = ['Embedded/industrial']
    channels = (
        {'id': 'nint', 'name': 'nINT_SDO_C', 'desc': 'nINT (and SDO outside sdo_int)'},
    )
    optional_channels = (
        {'id': 'cs', 'name': 'nSCS_C', 'desc': 'µC chip select'},
    )
    options = (
        {'id': 'settle', 'desc': 'ns after nSCS_C rises until the pin shows nINT', 'default': 1000},
    )
    annotations = (
        ('edge', 'nINT edge'),
        ('active', 'INT active'),
    )
    annotation_rows = (
        ('edges', 'Edges', (ANN_EDGE,)),
        ('int', 'INT', (ANN_ACTIVE,)),
    )

    def __init__(self):
        self.reset()

    def reset(self):
        self.samplerate = None
        self.level = None
        self.since = 0

    def start(self):
        self.out_ann = self.register(srd.OUTPUT_ANN)

    def metadata(self, key, value):
        if key == srd.SRD_CONF_SAMPLERATE:
            self.samplerate = value

    def seen(self, level):
        '''nINT shows `level` outside a frame at the current sample.'''
        ss = self.samplenum
        if self.level is not None and level != self.level:
            if level:
                self.put(ss, ss, self.out_ann, [ANN_EDGE, ['nINT rises (INT inactive)', 'rise']])
                self.put(self.since, ss, self.out_ann, [ANN_ACTIVE, ['INT active', 'INT']])
            else:
                self.put(ss, ss, self.out_ann, [ANN_EDGE, ['nINT falls (INT active)', 'fall']])
                self.since = ss
        self.level = level

    def decode(self):
        settle = 0
        if self.samplerate:
            settle = max(1, int(self.options['settle'] * 1e-9 * self.samplerate))
        # an unassigned channel reads 0xff (has_channel() of libsigrokdecode 0.5.3 miscounts
        # the references of the bools it returns)
        nint, cs = self.wait({})
        have_cs = cs in (0, 1)
        if not have_cs or cs == 1:
            self.seen(nint)
        while True:
            if not have_cs:
                nint, cs = self.wait({0: 'e'})
                self.seen(nint)
                continue
            nint, cs = self.wait([{0: 'e', 1: 'h'}, {1: 'r'}])
            if self.matched[0] and not self.matched[1]:
                self.seen(nint)
            elif self.matched[1]:
                # nINT_SDO_C leaves the last data bit a few CLK after nSCS_C rises
                nint, cs = self.wait([{'skip': settle}, {1: 'f'}])
                if self.matched[0]:
                    self.seen(nint)
