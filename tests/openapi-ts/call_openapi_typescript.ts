// A correct /v1/check and /v1/batch call typed by openapi-typescript's output
// (schema.d.ts, generated from GET /v1/openapi.json by run.sh): tsc must
// compile it, and must refuse the calls marked @ts-expect-error.
import type { components, paths } from "./schema";

type CheckBody = paths["/v1/check"]["post"]["requestBody"]["content"]["application/json"];
type BatchBody = paths["/v1/batch"]["post"]["requestBody"]["content"]["application/json"];
type CheckAnswer = paths["/v1/check"]["post"]["responses"]["200"]["content"]["application/json"];

const box = { bodies: [{ shape: "box", mass: 12, size: [1, 2, 3], position: [0, 0, 0] }] };

export const check: CheckBody = {
  operation: "/v1/rigid/inertia",
  request: box,
  answer: { pointer: "/principal/moments/0", value: "5.0 kg m^2" },
  tolerance: { significant_figures: 3, significant_figures_in: "answer" },
};

export const batch: BatchBody = {
  operations: [
    { operation: "/v1/rigid/inertia", request: box },
    { operation: "/v1/relativity/boost", request: { vectors: [[1, 0, 0, 0]], velocity: { beta: [0.6, 0, 0] } } },
  ],
};

// The shared pieces are named components.
export const nested: components["schemas"]["OperationRequest"] = box;
export const answer: components["schemas"]["CheckAnswer"] = { pointer: "/gamma", value: 1.25 };

export function verdict(r: CheckAnswer): string {
  const mistake: string | null = r.mistake;
  return (r.correct ? "right" : "wrong") + ": " + r.feedback + (mistake ? " (" + mistake + ")" : "");
}

// @ts-expect-error: answer is required
export const noAnswer: CheckBody = { operation: "/v1/rigid/inertia", request: box };
// @ts-expect-error: the request is an object, not a string
export const stringRequest: BatchBody = { operations: [{ operation: "/v1/rigid/inertia", request: "box" }] };
