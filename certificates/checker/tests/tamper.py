#!/usr/bin/python3
"""tamper.py — mutation tests of check_cert.

Usage: tamper.py CHECK_CERT TESTS_DIR WORKDIR [ASPECTS ROBOTS_DIR]

Each mutation takes a valid certificate (real PRRP and constrained RRRRR joint-limit
certificates solved by ASPECTS when it is given, and the golden certificates of
TESTS_DIR/valid), changes it, and states the exit code check_cert must give: 1 (REJECTED)
for a certificate that parses but claims something false, 2 (MALFORMED) for one that breaks
the format, 0 for a changed hint that still proves every claim; optionally also a word of
the message, when the reason matters (constraints). Every mutation must change the file and be applicable; the script fails
otherwise, so the suite cannot silently shrink.

The class "model edits that keep the tree" edits the embedded model and re-hashes it (byte
count and SHA-256 consistent), so the edit reaches the proofs: every variable's domain
narrowed, widened and shifted (always rejected), constants changed, constraints added and
removed, factors added, the robot renamed (rejected, or accepted only when every claim is
still true of the edited model; each case says which). Last, the exit statuses 3
(UNCHECKED: a bound resting on a user-supplied factor) and the --json verdict.
"""
import hashlib
import re
import json
import math
import os
import subprocess
import sys


from gen_corpus import hx  # C's %a form of a double, as the writer prints it


class Cert:
    """A certificate as lines; records are the lines after 'end-model'."""

    def __init__(self, text):
        self.lines = text.split("\n")
        assert self.lines[-1] == ""
        self.lines.pop()
        self.body = self.lines.index("end-model") + 1
        self.n = None

    def text(self):
        return "\n".join(self.lines) + "\n"

    def find(self, kind, start=None):
        return [i for i in range(start or self.body, len(self.lines)) if self.lines[i].split(" ")[0] == kind]

    def fields(self, i):
        return self.lines[i].split(" ")

    def set(self, i, fields):
        self.lines[i] = " ".join(fields)

    def rehash(self):
        """Recomputes 'model BYTES SHA' from the embedded lines and the 'end' count."""
        data = "\n".join(self.lines[3:self.body - 1]).encode()  # the text before the separator
        self.lines[2] = "model %d %s" % (len(data), hashlib.sha256(data).hexdigest())
        return self

    def fix_end(self):
        self.lines[-1] = "end %d" % (len(self.lines) - 1)
        return self


def dims(c):
    """n (equations) and nv (variables) from the domain record and an S record."""
    nv = (len(c.fields(c.find("domain")[0])) - 1) // 2
    return nv // 2, nv


def s_parts(c, i):
    n, _ = dims(c)
    f = c.fields(i)
    Q = [float.fromhex(x) for x in f[3:3 + 2 * n]]
    img = [float.fromhex(x) for x in f[3 + 2 * n:3 + 4 * n]]
    return f, n, Q, img


# ------------------------------------------------------------------ mutations
# Each returns the new text; `c` is a fresh Cert of the base.

def hash_digit(c):
    f = c.fields(2)
    f[2] = ("0" if f[2][0] != "0" else "1") + f[2][1:]
    c.set(2, f)
    return c.text()


def model_changed(c, rehash):
    i = next(k for k in range(3, c.body) if c.lines[k].startswith("constant l = 1"))
    c.lines[i] = "constant l = 2"
    return (c.rehash() if rehash else c).text()


def constraint_changed(c, old, new, rehash=True):
    i = next(k for k in range(3, c.body) if c.lines[k].startswith("constraint"))
    assert old in c.lines[i]
    c.lines[i] = c.lines[i].replace(old, new)
    return (c.rehash() if rehash else c).text()


def model_unparsable(c):
    i = next(k for k in range(3, c.body) if c.lines[k].startswith("equation"))
    c.lines[i] = c.lines[i].replace("=", "= +", 1).replace("^2", "^^2", 1)
    return c.rehash().text()


def replace_first(c, kind, fn):
    i = c.find(kind)[0]
    f = c.fields(i)
    fn(f)
    c.set(i, f)
    return c.text()


def sign_flip(c):
    i = next(i for i in c.find("S") if "+" in c.fields(i)[2] or "-" in c.fields(i)[2])
    f = c.fields(i)
    f[2] = f[2].replace("+", "x").replace("-", "+").replace("x", "-")
    c.set(i, f)
    return c.text()


def widen_across_singularity(c):
    """PRRP: widen the image of the S box nearest q = 0 (Fq = 2q) across it."""
    best = min(c.find("S"), key=lambda i: min(abs(v) for v in s_parts(c, i)[3]))
    f, n, Q, img = s_parts(c, best)
    m = max(abs(img[0]), abs(img[1]))
    f[3:5] = [hx(min(Q[0], -m) - 0.01), hx(max(Q[1], m) + 0.01)]
    f[5:7] = [hx(-m), hx(m)]
    c.set(best, f)
    return c.text()


def slab_holds_solution(c):
    """PRRP: a contraction of q right before an S record, moved into the solution's range."""
    for i in c.find("S"):
        if c.fields(i - 1)[0] == "P" and c.fields(i - 1)[1] == "1":
            f, n, Q, img = s_parts(c, i)
            p = c.fields(i - 1)
            p[2] = hx(0.5 * (img[0] + img[1]))
            c.set(i - 1, p)
            return c.text()
    raise AssertionError("no P on q before an S record")


def s_to_discard(c):
    i = c.find("S")[len(c.find("S")) // 2]
    c.lines[i] = "X hs"
    return c.text()


def link_other_aspect(c):
    """A K record whose B is replaced by a box of another CSNC (record order kept)."""
    ks = c.find("K")
    comps = [set(map(int, c.fields(j)[3:])) for j in c.find("csnc")]
    pairs = [tuple(map(int, c.fields(i)[1:3])) for i in ks]
    for k, i in enumerate(ks):
        a = pairs[k][0]
        mine = next(s for s in comps if a in s)
        for b in sorted(x for s in comps if s is not mine for x in s if x > a):
            if (k == 0 or pairs[k - 1] < (a, b)) and (k + 1 == len(ks) or (a, b) < pairs[k + 1]):
                f = c.fields(i)
                f[2] = str(b)
                c.set(i, f)
                return c.text()
    raise AssertionError("no order-preserving replacement")


def merge_components(c):
    cs = c.find("csnc")
    ids = sorted(set(map(int, c.fields(cs[0])[3:])) | set(map(int, c.fields(cs[1])[3:])))
    c.lines[cs[0]] = "csnc 0 %d %s" % (len(ids), " ".join(map(str, ids)))
    del c.lines[cs[1]]
    for k, j in enumerate(c.find("csnc")):
        f = c.fields(j)
        f[1] = str(k)
        c.set(j, f)
    c.lines[c.find("csncs")[0]] = "csncs %d" % len(c.find("csnc"))
    c.fix_end()
    return c.text()


def box_twice(c):
    """The last component listed twice: its boxes are then in two components."""
    cs = c.find("csnc")
    f = c.fields(cs[-1])
    f[1] = str(int(f[1]) + 1)
    c.lines.insert(cs[-1] + 1, " ".join(f))
    c.lines[c.find("csncs")[0]] = "csncs %d" % (len(cs) + 1)
    c.fix_end()
    return c.text()


def claim(c, which, delta):
    i = next(i for i in c.find("claim") if c.fields(i)[1] == which)
    f = c.fields(i)
    f[2] = str(int(f[2]) + delta)
    c.set(i, f)
    return c.text()


def perturb_hints(c, scale_c, widen_q):
    """Preconditioners times (1 + scale_c); Q~ widened by widen_q of its width."""
    n, nv = dims(c)
    for i in c.find("S") + c.find("K"):
        f = c.fields(i)
        if f[0] == "S":
            qs, cs = range(3, 3 + 2 * n, 2), range(3 + 4 * n, len(f))
        else:
            qs, cs = range(4 + n, 4 + 3 * n, 2), range(4 + 3 * n, len(f))
        for k in cs:
            f[k] = hx(float.fromhex(f[k]) * (1 + scale_c))
        for k in qs:
            lo, hi = float.fromhex(f[k]), float.fromhex(f[k + 1])
            f[k], f[k + 1] = hx(lo - widen_q * (hi - lo)), hx(hi + widen_q * (hi - lo))
        c.set(i, f)
    return c.text()


def narrow_images(c):
    """Every S record's IMAGE shrunk by 10% of its width on each side: a false claim."""
    n, _ = dims(c)
    for i in c.find("S"):
        f = c.fields(i)
        for k in range(3 + 2 * n, 3 + 4 * n, 2):
            lo, hi = float.fromhex(f[k]), float.fromhex(f[k + 1])
            f[k], f[k + 1] = hx(lo + 0.1 * (hi - lo)), hx(hi - 0.1 * (hi - lo))
        c.set(i, f)
    return c.text()


def edit(c, i, new):
    c.lines[i] = new
    return c.text()



# --------------------------------------------- model edits that keep the tree
# The embedded model is edited and re-hashed (byte count and SHA-256 consistent), while
# the tree, links and claims stay: the mutation reaches the proofs. A domain edit is always
# rejected (the root cell must be the declared domain rounded outward); any other edit is
# accepted only when every claim is still true of the edited model.

def model_line(c, prefix):
    return next(k for k in range(3, c.body - 1) if c.lines[k].startswith(prefix))


def model_edit(c, prefix, new):
    c.lines[model_line(c, prefix)] = new
    return c.rehash().text()


def model_add(c, line):
    c.lines.insert(c.body - 1, line)
    c.body += 1
    return c.rehash().fix_end().text()


def domains(c):
    """(name, kind, lo, hi, periodic) of each variable declared with numeric bounds."""
    out = []
    for k in range(3, c.body - 1):
        f = c.lines[k].split()
        if len(f) >= 4 and f[0] in ("pose", "command") and f[2] == "in":
            lo, hi = c.lines[k].split("[")[1].split("]")[0].split(",")
            out.append((f[1], f[0], lo.strip(), hi.strip(), "periodic" in f))
    return out


def domain_edit(c, name, how):
    """Narrowed (10% of the width off each end), widened (by 1 each side), shifted (by 10%
    of the width); a periodic domain keeps one period when shifted (`+ 0.5`)."""
    k = next(i for i in range(3, c.body - 1) if c.lines[i].split()[:2][-1:] == [name]
             and c.lines[i].split()[0] in ("pose", "command"))
    kind, _, _, per = next((d[1], d[2], d[3], d[4]) for d in domains(c) if d[0] == name)
    lo, hi = [x.strip() for x in c.lines[k].split("[")[1].split("]")[0].split(",")]
    w = "((%s) - (%s))" % (hi, lo)
    if how == "narrowed":
        lo, hi = "%s + 0.1*%s" % (lo, w), "%s - 0.1*%s" % (hi, w)
    elif how == "widened":
        lo, hi = "%s - 1" % lo, "%s + 1" % hi
    else:
        d = "0.5" if per else "0.1*%s" % w
        lo, hi = "%s + %s" % (lo, d), "%s + %s" % (hi, d)
    c.lines[k] = "%s %s in [%s, %s]%s" % (kind, name, lo, hi, " periodic" if per else "")
    return c.rehash().text()


def record_number_mutations(base_text):
    """A bad real on the tau and eps records is reported with that record's number (the
    checker once read the number before moving to the record: unspecified evaluation order)."""
    out = []
    for word in ("tau", "eps"):
        n = Cert(base_text).find(word)[0]
        out.append(("%s_bad_real_names_its_record" % word,
                    lambda c, n=n, word=word: edit(c, n, word + " 1.0"),
                    (2, "record %d: bad real" % (n + 1))))
    return out


def domain_mutations(base_text):
    """Every variable's domain narrowed, widened and shifted: always rejected. A periodic
    domain narrowed or widened is no longer one period: the embedded model is malformed (2)."""
    out = []
    for name, kind, lo, hi, per in domains(Cert(base_text)):
        for how in ("narrowed", "widened", "shifted"):
            want = (2, "not one period") if per and how != "shifted" else (1, "root cell")
            out.append(("domain_%s_%s" % (name, how),
                        lambda c, name=name, how=how: domain_edit(c, name, how), want))
    return out


def mutations_real(base):
    """(name, function of a fresh Cert, expected exit code) on a PRRP certificate."""
    return [
        ("hash_mismatch", lambda c: hash_digit(c), 1),
        ("model_constant_changed", lambda c: model_changed(c, False), 1),
        ("model_constant_changed_rehashed", lambda c: model_changed(c, True), 1),
        ("model_unparsable_rehashed", model_unparsable, 2),
        ("wrong_version", lambda c: edit(c, 0, "aspects-certificate 3"), 2),
        ("truncated_mid_record", lambda c: c.text()[: len(c.text()) // 2], 2),
        ("truncated_at_record", lambda c: "".join(l + "\n" for l in c.lines[:-3]), 2),
        ("garbage_bytes", lambda c: c.text().replace("\nS ", "\nS \x00\xff", 1), 2),
        ("content_after_end", lambda c: c.text() + "end 0\n", 2),
        ("crlf", lambda c: c.text().replace("\n", "\r\n", 1), 2),
        ("decimal_real", lambda c: replace_first(c, "B", lambda f: f.__setitem__(2, "0.0")), 2),
        ("extra_space", lambda c: replace_first(c, "S", lambda f: f.__setitem__(1, " " + f[1])), 2),
        ("end_count_wrong", lambda c: claim_end(c), 2),
        ("unknown_record_type", lambda c: replace_first(c, "B", lambda f: f.__setitem__(0, "Y")), 2),
        ("precision_out_of_range", lambda c: edit(c, c.body, "precision 8"), 2),
        ("record_dropped_link", lambda c: drop(c, c.find("K")[0]), 2),
        ("record_duplicated_link", lambda c: dup(c, c.find("K")[0]), 1),
        ("records_reordered_links", lambda c: swap(c, c.find("K")[0]), 1),
        ("record_dropped_tree", lambda c: drop(c, c.find("U")[0]), 1),
        ("record_duplicated_tree", lambda c: dup(c, c.find("S")[0]), 1),
        ("records_reordered_tree", lambda c: swap(c, c.find("S")[0] - 1), 1),
        ("solution_widened_across_singularity", widen_across_singularity, 1),
        ("preconditioner_zero", lambda c: replace_first(c, "S", lambda f: f.__setitem__(7, "0x0p+0")), 1),
        ("regularity_preconditioner_zero", lambda c: replace_first(c, "S", lambda f: f.__setitem__(8, "0x0p+0")), 1),
        ("coverage_violated", lambda c: replace_first(c, "S", lambda f: f.__setitem__(3, f[5])), 1),
        ("link_between_aspects", link_other_aspect, 1),
        ("link_witness_outside", lambda c: replace_first(c, "K", lambda f: f.__setitem__(4, hx(3.0))), 1),
        ("link_shift_on_nonperiodic", lambda c: replace_first(c, "K", lambda f: f.__setitem__(3, "+0")), 1),
        ("component_without_links", merge_components, 1),
        ("box_in_two_components", box_twice, 1),
        ("inflated_lower_bound", lambda c: claim(c, "lower-bound", 1), 1),
        ("wrong_filtered", lambda c: claim(c, "filtered", -1), 1),
        ("wrong_sign", sign_flip, 1),
        ("contraction_slab_holds_solution", slab_holds_solution, 1),
        ("discarded_cell_holds_solution", s_to_discard, 1),
        ("bisection_point_outside", lambda c: replace_first(c, "B", lambda f: f.__setitem__(2, hx(16.0))), 1),
        ("domain_narrowed", lambda c: replace_first(c, "domain", lambda f: f.__setitem__(1, hx(-1.5))), 1),
        ("factor_user_out_of_range", lambda c: edit(c, c.find("factor")[0], "factor user 1"), 1),
        ("output_id_out_of_order", lambda c: replace_first(c, "S", lambda f: f.__setitem__(1, str(int(f[1]) + 1))), 1),
        ("hint_preconditioner_perturbed", lambda c: perturb_hints(c, 1e-9, 0), 0),
        ("claim_images_narrowed", narrow_images, 1),
        # Model edits keeping the tree (re-hashed). Constants: a wider bar length moves
        # the solutions out of the recorded boxes (a refutation fails).
        # Issue 15: this forgery printed VERIFIED lower_bound=4 (the truth is 2).
        ("issue15_forgery_x_narrowed",
         lambda c: model_edit(c, "pose    x", "pose    x in [-2, -0.5]"), (1, "root cell")),
        ("model_constant_a_changed", lambda c: model_edit(c, "constant a", "constant a = 0.5"), 1),
        # The claim is still true of this model (l = 1 + 1e-15: 4 aspects) and every proof
        # keeps its margin: accepted.
        ("model_constant_l_changed_within_margins",
         lambda c: model_edit(c, "constant l", "constant l = 1.000000000000001"), 0),
        # A constraint true on the whole domain: every claim still holds, accepted.
        ("model_constraint_added_always_true", lambda c: model_add(c, "constraint x >= -3"), 0),
        # A constraint false on half of the solution boxes: the inner test fails.
        ("model_constraint_added_cuts", lambda c: model_add(c, "constraint x >= 0"),
         (1, "inner test")),
        # A factor in the model that the certificate does not use: the bound rests on detFx
        # and detFq only, so it is still true; accepted.
        ("model_factor_added_unused", lambda c: model_add(c, "factor x - 0.5"), 0),
        # The robot's name cannot forge the verdict line: quoted, after the real fields.
        ("model_name_forging_verdict",
         lambda c: model_edit(c, "robot", "robot PRRP csncs=9 lower_bound=99"),
         (0, 'lower_bound=4 checked_lower_bound=4 robot="PRRPcsncs=9lower_bound=99"')),
        # A '\r' in a comment: a terminal shows 'constant l = 2 #', the checker reads l = 1.
        # VERIFIED before (the model text was exempt from the ASCII rule).
        ("model_cr_in_comment_displays_another_model",
         lambda c: model_edit(c, "constant l", "constant l = 1 #\rconstant l = 2"),
         (2, "byte 13 in the model text")),
        # A bidi override in a comment (Trojan Source) likewise: VERIFIED before.
        ("model_bidi_override_in_comment",
         lambda c: model_edit(c, "constant a", "constant a = 0 # \u202e 2 = a tnatsnoc"),
         (2, "not printable ASCII")),
    ]


def mutations_constrained():
    """On RRRRR joint limit: (A' - P).(B' - P) >= 0 (FORMAT.md, "Constraints")."""
    return [
        # Stricter constraint: the recorded solution boxes no longer pass the inner test.
        ("constraint_tightened_inner_test", lambda c: constraint_changed(c, ">= 0", ">= 5"), (1, "inner test")),
        # Looser constraint: the cells discarded as X c0 now hold feasible solutions.
        ("constraint_relaxed_discard", lambda c: constraint_changed(c, ">= 0", ">= -5"), (1, "discarded cell")),
        # A solution cell (the constraint is True on its box) discarded as infeasible.
        ("discard_c0_of_feasible_cell", lambda c: edit(c, c.find("S")[len(c.find("S")) // 2], "X c0"),
         (1, "discarded cell")),
        ("constraint_changed_not_rehashed", lambda c: constraint_changed(c, ">= 0", ">= 5", False), (1, "SHA-256")),
        # Without the constraint its discards name no constraint (malformed); relabelled
        # as Hansen-Sengupta discards, the refutation itself must fail.
        ("constraint_removed_rehashed", lambda c: constraint_changed(c, "constraint", "# constraint"),
         (2, "bad hint")),
        ("constraint_removed_rehashed_relabelled",
         lambda c: re.sub(r"(?m)^X c\d+$", "X hs", constraint_changed(c, "constraint", "# constraint")),
         (1, "discarded cell")),
        ("discard_hint_c0_to_hs", lambda c: c.text().replace("\nX c0\n", "\nX hs\n"), 0),
        ("discard_hint_malformed", lambda c: c.text().replace("\nX c0\n", "\nX c00\n", 1), 2),
        # A second constraint true on the whole root cell (|x1| <= 40): accepted.
        ("constraint_added_always_true", lambda c: model_add(c, "constraint x1*x1 <= 1600"), 0),
        # A second constraint that cuts solution boxes: the inner test fails.
        ("constraint_added_cuts", lambda c: model_add(c, "constraint x1 >= 0"), (1, "inner test")),
    ]


def claim_end(c):
    c.lines[-1] = "end %d" % (len(c.lines) + 5)
    return c.text()


def drop(c, i):
    del c.lines[i]
    return c.text()


def dup(c, i):
    c.lines.insert(i, c.lines[i])
    return c.text()


def swap(c, i):
    c.lines[i], c.lines[i + 1] = c.lines[i + 1], c.lines[i]
    return c.text()


def mutations_golden():
    """(base file, name, function, expected) on the hand-made corpus."""
    return [
        ("line_split", "iterate_not_inside_inflated_box",
         lambda c: replace_first(c, "S", lambda f: f.__setitem__(3, hx(0.0))), 1),
        ("sine", "link_across_seam_without_shift",
         lambda c: replace_first_where(c, "K", lambda f: "-" in f[3] or "+" in f[3],
                                       lambda f: f.__setitem__(3, "00")), 1),
        ("sine", "hint_preconditioner_and_box_perturbed", lambda c: perturb_hints(c, 1e-9, 1e-9), 0),
        ("circle", "hint_preconditioner_and_box_perturbed", lambda c: perturb_hints(c, 1e-9, 1e-9), 0),
        ("circle", "claim_images_narrowed", narrow_images, 1),
        ("line_split", "discard_record_dropped", lambda c: drop(c, c.find("X")[0]), 1),
        ("line_split", "link_witness_not_a_double_point_of_both",
         lambda c: replace_first(c, "K", lambda f: f.__setitem__(4, hx(0.25))), 1),
        # complete=yes needs every U leaf at most eps wide (FORMAT.md, "U"): its U leaf is
        # 1 wide, so complete=no at eps 0.25 and complete=yes at eps 1.
        ("line_undecided", "eps_raised_to_the_undecided_width", lambda c: set_eps(c, 1.0),
         (0, " complete=yes eps=1 ")),
        ("circle", "eps_below_the_undecided_widths", lambda c: set_eps(c, 2.0 ** -10),
         (0, " complete=no eps=0.0009765625 ")),
    ]


def set_eps(c, eps):
    c.lines[c.find("eps")[0]] = "eps " + hx(eps)
    return c.text()


def replace_first_where(c, kind, pred, fn):
    i = next(i for i in c.find(kind) if pred(c.fields(i)))
    f = c.fields(i)
    fn(f)
    c.set(i, f)
    return c.text()


def run(check, path, env=None):
    """check_cert on one thread, on three with batches of three proofs (many batch
    boundaries), and with the trusted core alone (--trusted-only): the verdict, its record
    and its reason must depend neither on the threads nor on the speed layer. (Seen failing
    when the plain sweep of M left out the copies shifted by +-2*pi.)"""
    env = dict(os.environ, **(env or {}))
    r = subprocess.run([check, "--quiet", "--threads", "1", path], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, env=env)
    one = r.returncode, r.stdout.decode(errors="replace").strip()
    r = subprocess.run([check, "--quiet", "--threads", "3", path], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, env=dict(env, CHECK_CERT_BATCH="3"))
    three = r.returncode, r.stdout.decode(errors="replace").strip()
    if three != one:
        return -1, "threads change the verdict: %r against %r" % (three, one)
    r = subprocess.run([check, "--quiet", "--trusted-only", path], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, env=env)
    core = r.returncode, r.stdout.decode(errors="replace").strip()
    if core != one:
        return -1, "the speed layer changes the verdict: %r against %r" % (one, core)
    return one


def main():
    check, tests, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    bases = []  # (tag, path, mutations)
    if len(sys.argv) > 5:  # the real thing: certificates written by the solver
        aspects, robots = sys.argv[4], sys.argv[5]
        for robot, eps, muts in (("prrp", "0.1", mutations_real(None)), ("rprpr", "0.2", [
                                     # Issue 15: VERIFIED lower_bound=2 before (the truth is 1).
                                     ("issue15_forgery_x2_narrowed",
                                      lambda c: model_edit(c, "pose    x2",
                                                           "pose    x2 in [0.5, 20]"),
                                      (1, "root cell")),
                                     # P2's column weights (format 2): the last 2n fields.
                                     ("regularity_weight_not_positive",
                                      lambda c: replace_first(c, "S", lambda f: f.__setitem__(
                                          len(f) - 4, "-0x1p+0")), (1, "column weight")),
                                     ("regularity_weight_inflated",
                                      lambda c: replace_first(c, "S", lambda f: f.__setitem__(
                                          len(f) - 4, "0x1p+40")), (1, "P2"))]),
                                 ("rrrrr_joint_limit", "0.5", mutations_constrained())):
            subprocess.run([aspects, "solve", os.path.join(robots, robot + ".robot"), "--eps", eps,
                            "--out", os.path.join(work, robot), "--quiet"], check=True)
            path = os.path.join(work, robot, "aspects.cert")
            text = open(path).read()
            bases.append((robot, path, muts + domain_mutations(text) +
                          record_number_mutations(text)))
    else:
        bases.append(("circle", os.path.join(tests, "valid", "circle.cert"), mutations_real(None)))
    cases = []
    for tag, base_path, muts in bases:
        code, msg = run(check, base_path)
        if code != 0:
            print("FAIL base certificate %s not verified: %s" % (base_path, msg))
            return 1
        base = open(base_path).read()
        cases += [("%s/%s" % (tag, name), base, fn, want) for name, fn, want in muts]
    for file, name, fn, want in mutations_golden():
        cases.append(("%s/%s" % (file, name), open(os.path.join(tests, "valid", file + ".cert")).read(), fn, want))
    failed = 0
    for name, b, fn, want in cases:
        try:
            text = fn(Cert(b))
        except Exception as e:  # a mutation that does not apply is a failure of the suite
            print("FAIL %-55s mutation not applicable: %r" % (name, e))
            failed += 1
            continue
        if text == b:
            print("FAIL %-55s mutation changed nothing" % name)
            failed += 1
            continue
        path = os.path.join(work, name.replace("/", "__") + ".cert")
        with open(path, "w", newline="") as f:
            f.write(text)
        code, msg = run(check, path)
        want, word = want if isinstance(want, tuple) else (want, "")
        ok = code == want and word in msg
        print("%s %-55s exit %d (want %d%s): %s" % ("ok  " if ok else "FAIL", name, code, want,
                                                   ", '%s'" % word if word else "", msg[:110]))
        failed += not ok
    print("%d mutations, %d failed (bases: %s)" % (len(cases), failed, ", ".join(b[1] for b in bases)))
    if len(sys.argv) > 5:  # after the mutations: json_rejected reads one of their files
        failed += verdict_cases(check, sys.argv[4], sys.argv[5], work)
        failed += solved_cases(check, sys.argv[4], work)
        failed += witness_cases(check, sys.argv[4], work)
        failed += assembly_cases(check, sys.argv[4], work)
        failed += completeness_cases(check, sys.argv[4], sys.argv[5], work)
    failed += work_limit_cases(check, work)
    failed += width_rule_cases(check, work)
    return 1 if failed else 0


def verdict_cases(check, aspects, robots, work):
    """Exit statuses and the JSON verdict. A PRRP with a false user factor (x - 0.5 does not
    vanish only at singularities) claims 6 aspects; the truth is 4. check_cert cannot know
    the factor is false: exit 3 (UNCHECKED) unless --trust-factors."""
    model = os.path.join(work, "prrp_user_factor.robot")
    with open(os.path.join(robots, "prrp.robot")) as f, open(model, "w") as g:
        g.write(f.read() + "factor x - 0.5\n")
    out = os.path.join(work, "prrp_user_factor")
    subprocess.run([aspects, "solve", model, "--eps", "0.1", "--out", out, "--quiet"], check=True)
    uf = os.path.join(out, "aspects.cert")
    prrp = os.path.join(work, "prrp", "aspects.cert")
    forged = os.path.join(work, "prrp__domain_x_narrowed.cert")
    cases = [
        ("user_factor_unchecked", [uf], 3, "UNCHECKED"),
        ("user_factor_unchecked_says_why", [uf], 3, "lower_bound=6 checked_lower_bound=4"),
        ("user_factor_trusted", ["--trust-factors", uf], 0, "VERIFIED"),
        ("user_factor_json", ["--json", uf], 3, '"verdict":"UNCHECKED","exit":3'),
        ("json_verified", ["--json", prrp], 0, '"verdict":"VERIFIED","exit":0'),
        ("json_bound", ["--json", prrp], 0, '"lower_bound":4'),
        ("json_rejected", ["--json", forged], 1, '"verdict":"REJECTED","exit":1'),
    ]
    failed = 0
    for name, args, want, word in cases:
        r = subprocess.run([check, "--quiet"] + args, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT)
        msg = r.stdout.decode(errors="replace").strip()
        ok = r.returncode == want and word in msg
        if args[0] == "--json" and ok:
            ok = json.loads(msg)["exit"] == want
        print("%s verdict/%-47s exit %d (want %d, '%s'): %s" % ("ok  " if ok else "FAIL", name,
                                                              r.returncode, want, word, msg[:110]))
        failed += not ok
    return failed


# Models of their own for the forgeries below, solved by ASPECTS with these options.
SEAM = "robot SEAM\npose    x in %s\ncommand q in [-pi, pi] periodic\nequation x - sin(q) = 0\n"
SOLVED = {"seam24": (SEAM % "[-0.00000001, 0.00000001]", ["--prec", "24", "--eps", "1e-9"]),
          "seam53": (SEAM % "[0, 0]", ["--eps", "1e-3"])}


def drop_links(c):
    """No links and no CSNCs: the lower bound does not use them."""
    i, j = c.find("links")[0], c.find("claim")[0]
    c.lines[i:j] = ["links 0", "csncs 0"]
    c.lines[c.find("claim")[0]] = "claim filtered 0"
    return c.fix_end()


def solved_cases(check, aspects, work):
    """A periodic domain written with decimals close to pi is not one period: the declared
    domain misses a sliver at the seam. x = sin(q) has a second branch near q = pi, inside
    that sliver, so the truth is 1 aspect; the certificate (of the [-pi, pi] model, whose
    root cell is the same double interval) claims 2. Before the exact test of the periodic
    domain, check_cert printed VERIFIED lower_bound=2 for both (the width test passed by
    intervals: at 24 bits for 3.1415926, at 53 bits for 3.1415926535897932)."""
    cases = [
        ("periodic_domain_decimal_prec24", "seam24", "3.1415926",
         lambda c: drop_links(c), (2, "not one period (exactly")),
        ("periodic_domain_decimal_prec53", "seam53", "3.1415926535897932", lambda c: c,
         (2, "not one period (exactly")),
        # The same forms with pi: accepted (2 aspects is the truth on the whole circle).
        ("periodic_domain_pi_prec24", "seam24", "pi", lambda c: drop_links(c), (0, "VERIFIED")),
        ("periodic_domain_pi_prec53", "seam53", "pi", lambda c: c, (0, "VERIFIED")),
    ]
    failed = 0
    for name, model, bound, fn, (want, word) in cases:
        text, opts = SOLVED[model]
        out = os.path.join(work, model)
        if not os.path.exists(os.path.join(out, "aspects.cert")):
            with open(out + ".robot", "w") as f:
                f.write(text)
            subprocess.run([aspects, "solve", out + ".robot", "--out", out, "--quiet"] + opts,
                           check=True)
        c = fn(Cert(open(os.path.join(out, "aspects.cert")).read()))
        c.lines[model_line(c, "command q")] = "command q in [-%s, %s] periodic" % (bound, bound)
        path = os.path.join(work, "solved__%s.cert" % name)
        with open(path, "w") as f:
            f.write(c.rehash().text())
        code, msg = run(check, path)
        ok = code == want and word in msg
        print("%s solved/%-48s exit %d (want %d, '%s'): %s" % ("ok  " if ok else "FAIL", name, code,
                                                             want, word, msg[:110]))
        failed += not ok
    return failed


# One aspect covers every pose twice (q = x/2 and q = x/2 + pi on the torus): a toy robot
# with "one pose, two commands" witnesses (FORMAT.md, "Cuspidality witnesses").
DOUBLE_COVER = ("robot DOUBLE_COVER\npose    x in [-pi, pi] periodic\n"
                "command q in [-pi, pi] periodic\nequation sin(q + q - x) = 0\n")


def set_witnesses(c, records):
    """Replaces the cuspidal section by `records` (W lines)."""
    i = c.find("cuspidal")[0]
    j = c.find("claim")[0]
    c.lines[i:j] = ["cuspidal %d" % len(records)] + records
    return c.fix_end().text()


def components(c):
    return [list(map(int, c.fields(j)[3:])) for j in c.find("csnc")]


def witness_other_csnc(c):
    comps = components(c)
    a, b = sorted((comps[0][0], comps[1][0]))
    return set_witnesses(c, ["W 0 %d %d 00" % (a, b)])


def witness_commands_overlap(c):
    """A certified link: poses and commands meet, both boxes in one CSNC."""
    f = c.fields(c.find("K")[0])
    a, b = int(f[1]), int(f[2])
    k = next(k for k, ids in enumerate(components(c)) if a in ids)
    return set_witnesses(c, ["W %d %d %d %s" % (k, a, b, f[3])])


def witness_poses_disjoint(c):
    """A genuine witness with box B moved a period away on the pose x."""
    f = c.fields(c.find("W")[0])
    f[4] = {"0": "+", "-": "0", "+": "0"}[f[4][0]] + f[4][1:]
    return set_witnesses(c, [" ".join(f)])


def witness_cases(check, aspects, work):
    """The cuspidal section: PRRP has no witness; the toy DOUBLE_COVER has genuine ones,
    and forged witnesses are rejected with the reason."""
    out = os.path.join(work, "double_cover")
    with open(out + ".robot", "w") as f:
        f.write(DOUBLE_COVER)
    subprocess.run([aspects, "solve", out + ".robot", "--eps", "0.3", "--out", out, "--quiet"],
                   check=True)
    dc = open(os.path.join(out, "aspects.cert")).read()
    prrp = open(os.path.join(work, "prrp", "aspects.cert")).read()
    first_w = lambda c: c.fields(c.find("W")[0])
    cases = [
        ("prrp_has_no_witness", prrp, lambda c: c.text(), (0, " cuspidal=0 ")),
        # Every W record verified, at least one (207 when written).
        ("double_cover_verified", dc, lambda c: c.text(), (0, " cuspidal=")),
        ("double_cover_has_witnesses", dc, lambda c: c.text(), (0, "cuspidal_csncs=2")),
        ("witness_other_csnc", dc, witness_other_csnc, (1, "not both in the named CSNC")),
        ("witness_commands_overlap", dc, witness_commands_overlap,
         (1, "witness commands are not disjoint")),
        ("witness_poses_disjoint", dc, witness_poses_disjoint,
         (1, "witness poses do not overlap")),
        ("witness_undecided_box", prrp,
         lambda c: set_witnesses(c, ["W 0 %s %s 00" % tuple(sorted(
             (int(components(c)[0][0]), int(c.fields(c.find("U")[0])[1]))))]),
         (1, "not both solution boxes")),
        ("witness_shift_on_command", dc,
         lambda c: set_witnesses(c, [" ".join(first_w(c)[:4] + [first_w(c)[4][0] + "+"])]),
         (1, "shift on a command")),
        ("witness_unsorted", dc,
         lambda c: set_witnesses(c, [c.lines[c.find("W")[1]], c.lines[c.find("W")[0]]]),
         (1, "not sorted")),
        ("witness_bad_shift", dc,
         lambda c: set_witnesses(c, [" ".join(first_w(c)[:4] + ["0x"])]),
         (2, "bad SHIFT field")),
        ("witness_count_too_large", dc,
         lambda c: edit(c, c.find("cuspidal")[0], "cuspidal 999"),
         (2, "expected a W record")),
    ]
    failed = 0
    for name, base, fn, (want, word) in cases:
        path = os.path.join(work, "witness__%s.cert" % name)
        with open(path, "w") as f:
            f.write(fn(Cert(base)))
        code, msg = run(check, path)
        ok = code == want and word in msg
        print("%s witness/%-47s exit %d (want %d, '%s'): %s" % ("ok  " if ok else "FAIL", name,
                                                              code, want, word, msg[:110]))
        failed += not ok
    r = subprocess.run([check, "--quiet", "--json", os.path.join(out, "aspects.cert")],
                       stdout=subprocess.PIPE)
    v = json.loads(r.stdout) if r.returncode == 0 else {}
    ok = v.get("cuspidal", 0) > 0 and v.get("cuspidal_csncs") == 2
    print("%s witness/%-47s exit %d: %s" % ("ok  " if ok else "FAIL", "json_cuspidal",
                                            r.returncode, r.stdout.decode()[-80:].strip()))
    return failed + (not ok)


# Two poses for every command in one aspect: x = q/2 and q/2 + pi on the torus (periodic),
# and the squaring map of the complex plane around the origin (not periodic); each gives
# "one command, two poses" witnesses (FORMAT.md, "Assembly-mode witnesses").
DOUBLE_POSE = ("robot DOUBLE_POSE\npose    x in [-pi, pi] periodic\n"
               "command q in [-pi, pi] periodic\nequation sin(x + x - q) = 0\n")
COMPLEX_SQUARE = ("robot COMPLEX_SQUARE\npose x1 in [-2, 2]\npose x2 in [-2, 2]\n"
                  "command q1 in [-5, 5]\ncommand q2 in [-9, 9]\n"
                  "equation x1*x1 - x2*x2 - q1 = 0\nequation 2*x1*x2 - q2 = 0\n")


def set_assembly(c, records):
    """Replaces the assembly section by `records` (V lines); none: drops the section."""
    i = c.find("assembly")[0]
    j = c.find("claim")[0]
    c.lines[i:j] = ["assembly %d" % len(records)] + records if records is not None else []
    return c.fix_end().text()


def assembly_edit(c, fn):
    """The first V record of the DOUBLE_POSE certificate (n = 1), its fields edited by fn:
    V CSNC A B SHIFT Q* XA_LO XA_HI CA XB_LO XB_HI CB."""
    f = c.fields(c.find("V")[0])
    fn(f)
    return set_assembly(c, [" ".join(f)])


def assembly_pair(c, a, b):
    """The first V record with its boxes replaced by a and b (sorted), in the CSNC of a."""
    k = next(k for k, ids in enumerate(components(c)) if int(a) in ids)
    ids = [str(k)] + sorted([a, b], key=int)
    return assembly_edit(c, lambda f: f.__setitem__(slice(1, 4), ids))


def assembly_cases(check, aspects, work):
    """The assembly section: PRRP has none; the toys have genuine witnesses, and forged
    ones are rejected with the reason."""
    certs = {}
    for name, text in (("double_pose", DOUBLE_POSE), ("complex_square", COMPLEX_SQUARE)):
        out = os.path.join(work, name)
        with open(out + ".robot", "w") as f:
            f.write(text)
        subprocess.run([aspects, "solve", out + ".robot", "--eps", "0.3", "--out", out,
                        "--quiet"], check=True)
        certs[name] = open(os.path.join(out, "aspects.cert")).read()
    dp, sq = certs["double_pose"], certs["complex_square"]
    prrp = open(os.path.join(work, "prrp", "aspects.cert")).read()
    k0 = lambda c: c.fields(c.find("K")[0])
    cases = [
        ("prrp_has_none", prrp, lambda c: c.text(), (0, " assembly=0 ")),
        ("without_section_still_read", prrp, lambda c: set_assembly(c, None), (0, " assembly=0 ")),
        ("double_pose_verified", dp, lambda c: c.text(), (0, " assembly=86 ")),
        ("complex_square_verified", sq, lambda c: c.text(), (0, " assembly=116 ")),
        ("iterate_moved_to_other_box", dp,
         lambda c: assembly_edit(c, lambda f: f.__setitem__(slice(6, 8), f[9:11])),
         (1, "assembly: the pose is not in the box")),
        ("iterate_shifted", dp, lambda c: assembly_edit(c, lambda f: f.__setitem__(
            slice(6, 8), [hx(float.fromhex(x) + 0.05) for x in f[6:8]])), (1, "assembly: ")),
        ("q_outside_overlap", dp,
         lambda c: assembly_edit(c, lambda f: f.__setitem__(5, hx(float.fromhex(f[5]) + 1))),
         (1, "q* is not in both boxes' commands")),
        ("other_csnc", dp, lambda c: assembly_edit(c, lambda f: f.__setitem__(1, "1")),
         (1, "not both in the named CSNC")),
        ("boxes_in_two_csncs", dp,
         lambda c: assembly_pair(c, *[str(ids[0]) for ids in components(Cert(dp))[:2]]),
         (1, "not both in the named CSNC")),
        ("poses_not_disjoint", dp, lambda c: assembly_pair(c, k0(c)[1], k0(c)[2]),
         (1, "assembly poses are not disjoint")),
        ("shift_on_pose", dp, lambda c: assembly_edit(c, lambda f: f.__setitem__(4, "+0")),
         (1, "assembly shift on a pose")),
        ("unsorted", dp,
         lambda c: set_assembly(c, [c.lines[c.find("V")[1]], c.lines[c.find("V")[0]]]),
         (1, "not sorted")),
        ("count_too_large", dp, lambda c: edit(c, c.find("assembly")[0], "assembly 999"),
         (2, "expected a V record")),
    ]
    failed = 0
    for name, base, fn, (want, word) in cases:
        path = os.path.join(work, "assembly__%s.cert" % name)
        with open(path, "w") as f:
            f.write(fn(Cert(base)))
        code, msg = run(check, path)
        ok = code == want and word in msg
        print("%s assembly/%-46s exit %d (want %d, '%s'): %s" % ("ok  " if ok else "FAIL", name,
                                                               code, want, word, msg[:110]))
        failed += not ok
    return failed


def completeness_cases(check, aspects, robots, work):
    """complete=yes is established like the bound (FORMAT.md, "U" and "N"): a PRRP run
    stopped after 3 boxes leaves unexplored cells wider than eps; relabelled U they verify
    (the same claims) but not as complete. The full PRRP run is complete at its eps."""
    out = os.path.join(work, "prrp_partial")
    subprocess.run([aspects, "solve", os.path.join(robots, "prrp.robot"), "--eps", "0.1",
                    "--max-boxes", "3", "--threads", "1", "--out", out, "--quiet"])
    part = open(os.path.join(out, "aspects.cert")).read()
    full = open(os.path.join(work, "prrp", "aspects.cert")).read()
    unexplored = len(Cert(part).find("N"))
    relabel = lambda c: "".join(("U" + l[1:] if l.startswith("N ") else l) + "\n" for l in c.lines)
    cases = [
        ("partial", part, lambda c: c.text(), (0, " complete=no eps=0.1 ")),
        ("unexplored_relabelled_undecided", part, relabel,
         (0, " complete=no eps=0.1 solutions=0 undecided=%d unexplored=0 wide_undecided=%d "
          % (unexplored, unexplored))),
        # complete is relative to the eps it prints: at 1000 every cell is small enough.
        ("relabelled_and_eps_raised", part, lambda c: set_eps(Cert(relabel(c)), 1000.0),
         (0, " complete=yes eps=1000 ")),
        ("full", full, lambda c: c.text(), (0, " complete=yes eps=0.1 ")),
        ("full_eps_halved", full, lambda c: set_eps(c, 0.05), (0, " complete=no eps=0.05 ")),
    ]
    failed = 0 if unexplored >= 2 else 1
    for name, base, fn, (want, word) in cases:
        path = os.path.join(work, "complete__%s.cert" % name)
        with open(path, "w") as f:
            f.write(fn(Cert(base)))
        code, msg = run(check, path)
        ok = code == want and word in msg
        print("%s complete/%-46s exit %d (want %d, '%s'): %s" % ("ok  " if ok else "FAIL", name,
                                                               code, want, word, msg[:110]))
        failed += not ok
    return failed


def width_rule_cases(check, work):
    """The leaf rule compares widths with eps exactly: the root cell of x in [0.3, 1] is
    1 - RD(0.3) wide, which no double is (rounded to nearest it is below), so the largest
    double below the width gives complete=no and the smallest above it complete=yes; a
    test of the rounded width would say complete=yes for both."""
    from fractions import Fraction
    text = "robot WIDTH\npose x in [0.3, 1]\ncommand q in [0, 0.5]\nequation x - q = 0"
    lo = 0.3  # the enclosure of 0.3 rounded down: the double 0.3 is below 3/10
    assert Fraction(lo) < Fraction(3, 10)
    width = Fraction(1) - Fraction(lo)
    below = 1 - lo
    above = math.nextafter(below, 2)
    assert Fraction(below) < width < Fraction(above)
    failed = 0
    for eps, word in ((below, " complete=no "), (above, " complete=yes ")):
        b = text.encode()
        lines = ["aspects-certificate 2", "tool aspects 0.1.0",
                 "model %d %s" % (len(b), hashlib.sha256(b).hexdigest()), text, "end-model",
                 "precision 53", "tau 0x1p+0", "eps " + hx(eps),
                 "domain %s 0x1p+0 0x0p+0 0x1p-1" % hx(lo), "factors 0", "tree", "U 0 .",
                 "end-tree 1", "links 0", "csncs 0", "claim filtered 0", "claim lower-bound 0"]
        lines.append("end %d" % (len(lines) + text.count("\n")))
        path = os.path.join(work, "width_rule_%s.cert" % word.strip())
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        code, msg = run(check, path)
        ok = code == 0 and word in msg
        print("%s width/%-49s exit %d (want 0, '%s'): %s" % ("ok  " if ok else "FAIL", hx(eps),
                                                           code, word, msg[:110]))
        failed += not ok
    return failed


def work_bomb(terms=200):
    """A small certificate whose one discarded cell needs a refutation of 4095 boxes over a
    model of 1400 nodes (s - s is not 0 in intervals until the boxes are narrow). With 10^5
    nodes and 1000 such cells (1 MB) check_cert worked for days before the work limit."""
    s = " + ".join("sin(x + %d) + sin(q + %d)" % (k, k) for k in range(1, terms + 1))
    model = ("robot BOMB\npose x in [-2, 2]\ncommand q in [-2, 2]\nlet s = %s\n"
             "equation %r + 0.001*(s - s) = 0" % (s, 0.000075 * terms))
    b = model.encode()
    lines = ["aspects-certificate 1", "tool aspects 0.1.0",
             "model %d %s" % (len(b), hashlib.sha256(b).hexdigest()), model, "end-model",
             "precision 53", "tau 0x1p+0", "eps 0x1p+0", "domain -0x1p+1 0x1p+1 -0x1p+1 0x1p+1",
             "factors 0", "tree", "X hs", "end-tree 0", "links 0", "csncs 0", "claim filtered 0",
             "claim lower-bound 0"]
    lines.append("end %d" % (len(lines) + model.count("\n")))
    return "\n".join(lines) + "\n"


def one_image_bomb(cells=4000):
    """x = q over [-2, 2]^2 cut into `cells` slices of q, every slice a solution leaf with the
    same box (cell_x, IMAGE) = [-2, 2]^2: every pair of boxes are neighbours, M has 8*10^6
    pairs (10^5 slices: 5*10^9 pairs, 40 GB, from a 9 MB certificate)."""
    model = "robot LINE\npose x in [-2, 2]\ncommand q in [-2, 2]\nequation x - q = 0"
    b = model.encode()
    lines = ["aspects-certificate 1", "tool aspects 0.1.0",
             "model %d %s" % (len(b), hashlib.sha256(b).hexdigest()), model, "end-model",
             "precision 53", "tau 0x1p+0", "eps 0x1p+0", "domain -0x1p+1 0x1p+1 -0x1p+1 0x1p+1",
             "factors 0", "tree"]
    leaf = " . %s %s -0x1p+1 0x1p+1 0x1p+0 0x1p+0 0x1p+0" % (hx(-2.5), hx(2.5))
    for i in range(cells):
        if i < cells - 1:
            lines.append("B 1 %s" % hx(-2 + 4.0 * (i + 1) / cells))
        lines.append("S %d%s" % (i, leaf))
    lines += ["end-tree %d" % cells, "links 0", "csncs 0", "claim filtered 0", "claim lower-bound 1"]
    lines.append("end %d" % (len(lines) + model.count("\n")))
    return "\n".join(lines) + "\n"


def work_limit_cases(check, work):
    """The work limit grows with the certificate's size (2^29 units plus 2^10 per byte);
    CHECK_CERT_WORK_BASE=20 lowers its base so that the test is quick."""
    path = os.path.join(work, "work_bomb.cert")
    with open(path, "w") as f:
        f.write(work_bomb())
    quadratic = os.path.join(work, "one_image_bomb.cert")
    with open(quadratic, "w") as f:
        f.write(one_image_bomb())
    failed = 0
    for name, env, want, word, path in (
            ("work_limit_exceeded", "20", 1, "more work than the checker", path),
            ("work_limit_default", "29", 0, "VERIFIED", path),
            # VERIFIED before, with 4000 boxes; 10^5 would have exhausted memory.
            ("neighbourhood_graph_quadratic", "29", 1, "2^22 + 64 pairs per box", quadratic),
            ("neighbourhood_graph_fits", "29", 0, "VERIFIED", None)):
        if path is None:
            path = os.path.join(work, "one_image_small.cert")
            with open(path, "w") as f:
                f.write(one_image_bomb(200))
        code, msg = run(check, path, {"CHECK_CERT_WORK_BASE": env})
        ok = code == want and word in msg
        print("%s limit/%-49s exit %d (want %d, '%s'): %s" % ("ok  " if ok else "FAIL", name,
                                                            code, want, word, msg[:110]))
        failed += not ok
    return failed


if __name__ == "__main__":
    sys.exit(main())
