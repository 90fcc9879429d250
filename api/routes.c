/* routes.c — the route table: every operation mechd serves. The catalog
 * (GET /v1), the OpenAPI document and the README's endpoint table all come
 * from these entries. Add a route here and nowhere else. The envelope keys
 * (api_envelope_properties) are added here to every POST route's schema. */
#include "routes.h"

#include <stdio.h>

extern const struct api_route api_route_rigid_inertia;
extern const struct api_route api_route_vectors;
extern const struct api_route api_route_tensor_symmetric;
extern const struct api_route api_route_relativity_boost;
extern const struct api_route api_route_trajectory;
extern const struct api_route api_route_compare;
extern const struct api_route api_route_frames_effective_force;
extern const struct api_route api_route_frames_rotating_liquid;
extern const struct api_route api_route_earth_gravity;
extern const struct api_route api_route_earth_tides;
extern const struct api_route api_route_scene_falling_object;
extern const struct api_route api_route_scene_vertical_shot;
extern const struct api_route api_route_scene_cannonball;
extern const struct api_route api_route_scene_foucault;
extern const struct api_route api_route_scene_rotating_table;
extern const struct api_route api_route_integrators;
extern const struct api_route api_route_check;
extern const struct api_route api_route_batch;
extern const struct api_route api_route_examples;
extern const struct api_route api_route_rotation_convert;
extern const struct api_route api_route_rotation_compose;
extern const struct api_route api_route_rotation_apply;
extern const struct api_route api_route_rotation_euler_rates;
extern const struct api_route api_route_rigid_rotate;
extern const struct api_route api_route_rigid_top;
extern const struct api_route api_route_rigid_stability;
extern const struct api_route api_route_rigid_free_symmetric_top;
extern const struct api_route api_route_rigid_struck_ball;
extern const struct api_route api_route_rigid_topple;
extern const struct api_route api_route_small_oscillations;
extern const struct api_route api_route_relativity_velocity_addition;
extern const struct api_route api_route_relativity_interval;
extern const struct api_route api_route_relativity_worldline;
extern const struct api_route api_route_relativity_doppler;
extern const struct api_route api_route_relativity_fields;
extern const struct api_route api_route_relativity_invariant_mass;
extern const struct api_route api_route_relativity_decay;
extern const struct api_route api_route_relativity_compton;
extern const struct api_route api_route_relativity_elastic;
extern const struct api_route api_route_relativity_collision;
extern const struct api_route api_route_relativity_particles;
extern const struct api_route api_route_relativity_particle;
extern const struct api_route api_route_relativity_dot;
extern const struct api_route api_route_relativity_rocket;
extern const struct api_route api_route_relativity_force;
extern const struct api_route api_route_relativity_lagrangian;
extern const struct api_route api_route_relativity_michelson_morley;
extern const struct api_route api_route_gr_schwarzschild;
extern const struct api_route api_route_gr_geodesic;
extern const struct api_route api_route_hamiltonian_flow;
extern const struct api_route api_route_hamiltonian_liouville;
extern const struct api_route api_route_hamiltonian_poincare;
extern const struct api_route api_route_hamiltonian_phase_area;
extern const struct api_route api_route_hamiltonian_rotating_frame;
extern const struct api_route api_route_hamiltonian_circular_orbit;
extern const struct api_route api_route_continuum_string;
extern const struct api_route api_route_continuum_rod;

const struct api_route *const api_routes[] = {
    &api_route_vectors,
    &api_route_tensor_symmetric,
    &api_route_rotation_convert,
    &api_route_rotation_compose,
    &api_route_rotation_apply,
    &api_route_rotation_euler_rates,
    &api_route_rigid_inertia,
    &api_route_rigid_rotate,
    &api_route_rigid_top,
    &api_route_rigid_stability,
    &api_route_rigid_free_symmetric_top,
    &api_route_rigid_struck_ball,
    &api_route_rigid_topple,
    &api_route_small_oscillations,
    &api_route_relativity_boost,
    &api_route_relativity_particle,
    &api_route_relativity_dot,
    &api_route_relativity_rocket,
    &api_route_relativity_force,
    &api_route_relativity_lagrangian,
    &api_route_relativity_michelson_morley,
    &api_route_relativity_velocity_addition,
    &api_route_relativity_interval,
    &api_route_relativity_worldline,
    &api_route_relativity_doppler,
    &api_route_relativity_fields,
    &api_route_relativity_invariant_mass,
    &api_route_relativity_decay,
    &api_route_relativity_compton,
    &api_route_relativity_elastic,
    &api_route_relativity_collision,
    &api_route_relativity_particles,
    &api_route_gr_schwarzschild,
    &api_route_gr_geodesic,
    &api_route_hamiltonian_flow,
    &api_route_hamiltonian_liouville,
    &api_route_hamiltonian_poincare,
    &api_route_hamiltonian_phase_area,
    &api_route_hamiltonian_rotating_frame,
    &api_route_hamiltonian_circular_orbit,
    &api_route_continuum_string,
    &api_route_continuum_rod,
    &api_route_trajectory,
    &api_route_compare,
    &api_route_frames_effective_force,
    &api_route_frames_rotating_liquid,
    &api_route_earth_gravity,
    &api_route_earth_tides,
    &api_route_scene_falling_object,
    &api_route_scene_vertical_shot,
    &api_route_scene_cannonball,
    &api_route_scene_foucault,
    &api_route_scene_rotating_table,
    &api_route_integrators,
    &api_route_check,
    &api_route_batch,
    &api_route_examples,
};
const size_t api_route_count = sizeof api_routes / sizeof api_routes[0];

const char api_envelope_properties[] = "{\"cost\":" API_ENVELOPE_COST_SCHEMA "}";

int api_route_schema_add_envelope(json_t *schema, char *msg, size_t n)
{
    json_t *props = json_object_get(schema, "properties");
    if (!json_is_object(props)) {
        snprintf(msg, n, "the root schema has no properties to add the envelope keys to");
        return -1;
    }
    json_t *env = json_loads(api_envelope_properties, 0, NULL);
    if (!env) {
        snprintf(msg, n, "out of memory (or a broken envelope text)");
        return -1;
    }
    const char *key;
    json_t *val;
    json_object_foreach(env, key, val) {
        if (json_object_get(props, key)) {
            snprintf(msg, n, "declares the envelope key '%s' at its root; the route table adds it",
                     key);
            json_decref(env);
            return -1;
        }
        if (json_object_set(props, key, val)) {
            snprintf(msg, n, "out of memory");
            json_decref(env);
            return -1;
        }
    }
    json_decref(env);
    return 0;
}
