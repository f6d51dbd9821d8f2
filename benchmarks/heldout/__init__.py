"""Independent held-out crash tests for the loop: data that can surprise it.

- ``physics.py``: a thorax (spine, sternum on two masses), belt (chest-side webbing, webbing
  to the retractor, D-ring friction) and retractor (pretensioner, ratchet, torsion-bar load
  limiter) integrated by RK4 at 20 kHz, and crash pulses (R16 sled, sled with interior,
  barrier crush). Written from the physics; nothing from ``observer_node`` is imported.
- ``lab.py``: per-test scatter of the dummy (5 % 1-sigma, clipped at 10 %), lab noise, BRS
  counts (48, 64, 96 or 128 per rev), CFC 180 / 600 filters, SAE J211 signs, rig metadata.
- ``iso_mme.py``: the ISO-MME writer.  ``cases.py``: set A, the held-out cases and their
  expected verdicts (now seen by the loop's engineers).  ``cases_b.py``: set B, new cases and
  verdicts committed before the loop ran on them (now seen too).  ``cases_c.py``: set C, the
  same again, on two-setup mixes, with a case outside the loop's vocabulary.
  ``cases_d.py``: set D, the same again, on lopsided and single-setup mixes.
  ``cases_e.py``: set E, on pairings of setup counts no earlier case ran; ``cases_f.py``:
  set F, the same again, with lab-side faults of new kinds; ``cases_g.py``: set G, the same
  again (a CD rail, a pulse on its own time base, a CD dead band); ``cases_h.py``: set H,
  the same again, with three physical forms no earlier set used (squeeze-film damping in the
  chest, a bag leaking through its fabric, a pelvis submarining under its lap belt);
  ``cases_i.py``: set I, the same again, with a chest locking up as it nears its limit (a
  hyperbolic spring) and lab-side faults of new kinds (a BRS polled too slowly, a CR recorder
  losing a block of samples, a chest pot lagging on its linkage).
  ``cases_j.py``: set J, the same again, estimated on every rig and mostly validated on two,
  with a rib cage stiffening by Fung's exponential law and lab-side faults of new kinds (a
  spine accelerometer loose on its mount, two tests' BRS files crossed, a chest pot arm
  lifting off the sternum as the chest opens).
  ``cases_k.py``: set K, the same again, on pairings no earlier case ran, with a driver bag on
  a two-stage inflator and lab-side faults of new kinds (a pulse channel copied from another
  run, the only estimation test of its rig; a spine accelerometer's zero shifting under the
  shock).
  ``cases_l.py``: set L, the same again, on pairings no earlier case ran, with a knee bolster
  on the pelvis path and lab-side faults of new kinds (a pulse module sampling at another rate
  than its file states; a chest pot's anti-alias filter set far too low, delaying CD).
  ``cases_m.py``: set M, the same again, on pairings no earlier case ran, judging scope (rigs
  held by few estimation tests or none), with viscoelastic rib material (a Maxwell branch) and
  a capstan at the D-ring, and lab-side faults of new kinds (a test run with another dummy
  than its file names; CR picking up CD on a multiplexed digitiser).
  ``cases_n.py``: set N, the same again, on pairings no earlier case ran, judging scope again
  (a rig held by a single estimation test or none beside the rigs an effect is on), with
  lab-side faults of new kinds (an estimation test run with a cold-soaked dummy; a chest pot
  whose excitation sags after the trigger).
  ``cases_o.py``: set O, the same again, on pairings no earlier case ran, judging two effects
  of different kinds on different rigs and whether a second effect is invented beside one,
  with dry friction in the rib cage and lab-side faults of new kinds (a BRS file holding the
  spindle's raw counts where its header says degrees; an oil-damped spine accelerometer too
  slow for a crash).
  ``cases_p.py``: set P, the same again, on pairings no earlier case ran, judging the belt's
  unloading path (a webbing's permanent set, its hysteresis, a capstan at the car's D-ring, at
  new sizes and scopes) against clean cases and two effects that must not be named as one.
  ``cases_q.py``: set Q, the same again, on pairings no earlier case ran, judging timing: a
  late input (the pulse; the BRS) against a late or lagging output (CR written late by its
  digitiser; CD through a one-pole RC low-pass; both outputs late on the dummy's recorder).
  ``cases_r.py``: set R, the same again, on pairings no earlier case ran: the general list
  (clean cases, each kind of the library as physics, two effects on two rigs, a broken test, a
  transducer error on CD, a late pulse and a late BRS) at new seeds, sizes and scopes.
  ``cases_s.py``: set S, the same again, on pairings no earlier case ran, by another engineer:
  the general list at new seeds, sizes and scopes, with a rib cage damped by a constant loss
  factor (hysteretic damping), a BRS counter of too few bits wrapping round (broken test) and
  a spine accelerometer whose gauges creep (a transducer error on CR).
  ``cases_t.py``: set T, the same again, on pairings no earlier case ran, by another engineer,
  judging sensor against physics: a transducer error on CD alone (a chest pot's arm ringing)
  and one on CR alone (a spine accelerometer's zero drifting from the trigger) beside physical
  effects that show mostly in one output (a stop behind the lower sternum, a new form), and the
  general list's rest (a pulse channel written in m/s^2 under its g: a broken test).
  ``cases_u.py``: set U, the same again, on pairings no earlier case ran, by another engineer:
  the general list with the library's ordinary physical forms (the form an engineer would
  first write for each kind) on all three rigs or on two, at new seeds and sizes, a pulse
  cable parting mid-crash (broken test) and a chest pot loaded by its conditioner (a
  transducer error on CD).
  ``cases_v.py``: set V, the same again, on pairings no earlier case ran, by another engineer:
  the general list with every choice drawn by a seeded generator (``draw_v.py``: forms, rigs,
  mixes, counts, delays, the broken channel, the transducer's output), the sizes set by costs,
  a CR conditioner on too small a range (broken test) and a CR module's clock running slow (a
  transducer error on CR).
  ``cases_w.py``: set W, the same again, on pairings no earlier case ran, by another engineer:
  the general list with every choice drawn by a seeded generator (``draw_w.py``, set V's
  process at 32000, the transducer error's and the broken test's forms drawn as well, among
  every lab-side form the simulator has), the sizes set by costs, and a CD module's clock
  running slow (``cd_clock``, a transducer form drawn into the pool beside the others).
  ``cases_x.py``: set X, the same again, on pairings no earlier case ran, by another engineer:
  set W's process at 33000 (``draw_x.py``), every choice drawn, the sizes set by costs by a
  rule written before the draw.
  ``cases_y.py``: set Y, the same again, on pairings no earlier case ran, by another engineer:
  set X's process at 34000 (``draw_y.py``), every choice drawn, the sizes set by costs by a
  rule written before the draw.
  ``cases_z.py``: set Z, the same again, by another engineer: set Y's process at 35000
  (``draw_z.py``), every choice drawn, the sizes set by costs by a rule written before the
  draw, on pairings no earlier case ran save the two-effect case's (none was left for it: it
  reuses one of set O's, by a rule written before drawing again).
  ``cases_aa.py``: set AA, the same again, by another engineer: set Z's process at 36000
  (``draw_aa.py``), every choice drawn, the sizes set by costs by a rule written before the
  draw, on pairings no earlier case ran save the two-effect case's (none was left for it: it
  reuses one of set J's, by set Z's rule, written into draw_aa.py before the draw).
  ``make_sets.py``: writes a set (``--no-effects``: the same tests with every effect off).
  ``costs.py``: what each case costs the thesis grey-box (project CLI).

    python -m benchmarks.heldout.make_sets --out /tmp/heldout
        [--set a|b|c|d|e|f|g|h|i|j|k|l|m|n|o|p|q|r|s|t|u|v|w|x|y|z|aa] [--case NAME ...]

Never tune the loop on these cases; report them apart from the tuned ones.
"""
