// A correct /v1/check and /v1/batch call typed by @hey-api/openapi-ts's output
// (hey/types.gen.ts, generated from GET /v1/openapi.json by run.sh): tsc must
// compile it, and must refuse the calls marked @ts-expect-error.
import type { BatchData, CheckAnswer, CheckData, OperationRequest } from "./hey/types.gen";

const box = { bodies: [{ shape: "box", mass: 12, size: [1, 2, 3], position: [0, 0, 0] }] };

export const check: CheckData["body"] = {
  operation: "/v1/rigid/inertia",
  request: box,
  answer: { pointer: "/principal/moments/0", value: 5.001, unit: "kg m^2" },
  tolerance: { relative: 0.01 },
};

export const batch: BatchData["body"] = {
  operations: [{ operation: "/v1/rigid/inertia", request: box }],
};

export const nested: OperationRequest = box;
export const answer: CheckAnswer = { pointer: "/gamma", value: "1.25" };

// @ts-expect-error: answer is required
export const noAnswer: CheckData["body"] = { operation: "/v1/rigid/inertia", request: box };
