/* mech/ode/accuracy.h — the accuracy presets every operation that chooses by
 * accuracy shares ({"accuracy": "draft" | "balanced" | "precise" |
 * "machine"}): a preset is a target relative error handed to the predictive
 * chooser (mech/ode/chooser.h); core/ode/accuracy.c holds the table, and
 * docs/accuracy.md what each promise means and how it is measured. */
#ifndef MECH_ACCURACY_H
#define MECH_ACCURACY_H

enum mech_accuracy {
    MECH_ACCURACY_DRAFT = 0,
    MECH_ACCURACY_BALANCED,
    MECH_ACCURACY_PRECISE,
    MECH_ACCURACY_MACHINE,
    MECH_ACCURACY_COUNT
};

/* An accuracy preset: what it promises (the chooser's target) and, for the
 * API's listing of the integrators, what the chooser typically picks on a 10-orbit Kepler
 * scene (the choice itself is made per scene by mech/ode/chooser.h). */
struct mech_accuracy_preset {
    const char *name;         /* "draft", "balanced", "precise", "machine" */
    double promise;           /* relative error on positions and velocities it aims at */
    const char *method;       /* typical method, velocity-free scenes */
    const char *method_other; /* typical method, velocity-dependent scenes */
    double rtol;              /* its typical rtol */
    double rtol_other;        /* its typical rtol */
    const char *doc;
};

const struct mech_accuracy_preset *mech_accuracy_preset_at(enum mech_accuracy a); /* NULL if out of range */

/* The preset called `name` ("draft", "balanced", "precise", "machine"); NULL
 * when name is NULL or names none. The table is static: never freed. */
const struct mech_accuracy_preset *mech_accuracy_preset_named(const char *name);

/* The target relative error of a request's accuracy block: `target_error`
 * when the block gives one (target_error_given != 0), else the promise of the
 * preset `name`, else (NULL or unknown name) the default preset's,
 * "balanced". *preset (if not NULL) is set to the preset used, NULL when
 * target_error was given. Pure; no range check (mech_choose checks the
 * target: [1e-15, 0.1]). */
double mech_accuracy_target(int target_error_given, double target_error, const char *name,
                            const struct mech_accuracy_preset **preset);

#endif
