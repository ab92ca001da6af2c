##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

import sigrokdecode as srd


class Decoder(srd.Decoder):
    api_version = 3
    id = 'tmc429_stepdir'
    name = 'TMC429 Step/Dir'
    longname = 'Trinamic TMC429/TMC4210 Step/Dir'
    desc = 'Steps, direction and position of up to three motors.'
    license = 'mit'
    inputs = ['logic']
    outputs = []
    tags = ['Embedded/industrial']
    channels = (
        {'id': 'step1', 'name': 'STEP1', 'desc': 'STEP of motor 0 (SDO_S)'},
        {'id': 'dir1', 'name': 'DIR1', 'desc': 'DIR of motor 0 (SCK_S)'},
    )
    optional_channels = (
        {'id': 'step2', 'name': 'STEP2', 'desc': 'STEP of motor 1 (nSCS_S)'},
        {'id': 'dir2', 'name': 'DIR2', 'desc': 'DIR of motor 1 (SDI_S)'},
        {'id': 'step3', 'name': 'STEP3', 'desc': 'STEP of motor 2 (nSCS2)'},
        {'id': 'dir3', 'name': 'DIR3', 'desc': 'DIR of motor 2 (nSCS3)'},
    )
    options = (
        {'id': 'step_half', 'desc': 'step_half: both STEP edges are steps', 'default': 'no', 'values': ('no', 'yes')},
        {'id': 'inv_stp', 'desc': 'inv_stp: STEP active low', 'default': 'no', 'values': ('no', 'yes')},
        {'id': 'inv_dir', 'desc': 'inv_dir: DIR low is negative', 'default': 'no', 'values': ('no', 'yes')},
    )
    annotations = (
        ('step0', 'Step motor 0'), ('step1', 'Step motor 1'), ('step2', 'Step motor 2'),
        ('pos0', 'Position motor 0'), ('pos1', 'Position motor 1'), ('pos2', 'Position motor 2'),
    )
    annotation_rows = (
        ('motor0', 'Motor 0', (0,)), ('position0', 'Position 0', (3,)),
        ('motor1', 'Motor 1', (1,)), ('position1', 'Position 1', (4,)),
        ('motor2', 'Motor 2', (2,)), ('position2', 'Position 2', (5,)),
    )

    def __init__(self):
        self.reset()

    def reset(self):
        self.pos = [0, 0, 0]
        self.last = [None, None, None]

    def start(self):
        self.out_ann = self.register(srd.OUTPUT_ANN)

    def step(self, m, negative):
        ss = self.samplenum
        self.pos[m] += -1 if negative else 1
        sign = '-' if negative else '+'
        self.put(ss, ss, self.out_ann, [m, ['%s %d' % (sign, self.pos[m]), sign]])
        if self.last[m] is not None:
            self.put(self.last[m][0], ss, self.out_ann, [3 + m, ['%d' % self.last[m][1]]])
        self.last[m] = (ss, self.pos[m])

    def decode(self):
        # an unassigned channel reads 0xff (has_channel() of libsigrokdecode 0.5.3 miscounts
        # the references of the bools it returns)
        pins = self.wait({})
        motors = [m for m in range(3) if pins[2 * m] in (0, 1) and pins[2 * m + 1] in (0, 1)]
        half = self.options['step_half'] == 'yes'
        active = 0 if self.options['inv_stp'] == 'yes' else 1
        inv_dir = self.options['inv_dir'] == 'yes'
        edge = 'e' if half else ('r' if active else 'f')
        conds = [{2 * m: edge} for m in motors]
        while True:
            pins = self.wait(conds)
            for k, m in enumerate(motors):
                if self.matched[k]:
                    self.step(m, bool(pins[2 * m + 1]) != inv_dir)
