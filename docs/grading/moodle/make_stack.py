#!/usr/bin/python3
"""Write stack_box_moments.xml: a Moodle STACK question (Moodle XML export) whose
Maxima question variables hold mechd's answers. STACK's Maxima cannot call mechd, so
the answers for every parameter set are computed here, in one /v1/batch through the
offline evaluator, when the question is written:

    MECHD_EVAL=build/mechd-eval python3 docs/grading/moodle/make_stack.py > docs/grading/moodle/stack_box_moments.xml

tests/integration/test_grading_questions.py regenerates it and compares.
"""
import json
import os
import subprocess

# (mass kg, edges a, b, c m): every set gives other moments.
SETS = [(12, 1, 2, 3), (6, 1, 1, 2), (2, 0.5, 1, 1.5), (3, 2, 2, 4), (10, 0.3, 0.4, 1.2),
        (4, 1, 3, 3)]
TOLERANCE = 0.005  # NumRelative: 0.5 %, far above mechd's recommended 1e-12 (closed form)


def answers():
    env = {"operation": "/v1/batch", "request": {"operations": [
        {"operation": "/v1/rigid/inertia",
         "request": {"bodies": [{"shape": "box", "mass": m, "size": [a, b, c],
                                 "position": [0, 0, 0]}]}} for m, a, b, c in SETS]}}
    out = subprocess.run([os.environ.get("MECHD_EVAL", "mechd-eval")], input=json.dumps(env).encode(),
                         capture_output=True, timeout=60, check=True).stdout
    return [r["body"]["principal"]["moments"] for r in json.loads(out)["results"]]


def maxima_list(xs):
    return "[" + ",".join(repr(x) for x in xs) + "]"


def question(moments):
    variables = "\n".join([
        "/* Parameter sets [m, a, b, c] and mechd's principal moments (/v1/rigid/inertia),",
        "   written by docs/grading/moodle/make_stack.py: do not edit by hand. */",
        "P: %s;" % maxima_list([list(s) for s in SETS]).replace(" ", ""),
        "Imins: %s;" % maxima_list([mo[0] for mo in moments]),
        "Imaxs: %s;" % maxima_list([mo[2] for mo in moments]),
        "k: 1 + rand(length(P));",
        "m: P[k][1]; a: P[k][2]; b: P[k][3]; c: P[k][4];",
        "Imin: Imins[k];",
        "Imax: Imaxs[k];",
    ])
    node = """      <node>
        <name>{n}</name>
        <description></description>
        <answertest>NumRelative</answertest>
        <sans>{sans}</sans>
        <tans>{tans}</tans>
        <testoptions>{tol}</testoptions>
        <quiet>0</quiet>
        <truescoremode>+</truescoremode>
        <truescore>0.5</truescore>
        <truepenalty></truepenalty>
        <truenextnode>{next}</truenextnode>
        <trueanswernote>prt1-{n1}-T</trueanswernote>
        <truefeedback format="html"><text></text></truefeedback>
        <falsescoremode>+</falsescoremode>
        <falsescore>0</falsescore>
        <falsepenalty></falsepenalty>
        <falsenextnode>{next}</falsenextnode>
        <falseanswernote>prt1-{n1}-F</falseanswernote>
        <falsefeedback format="html"><text><![CDATA[<p>{fb}</p>]]></text></falsefeedback>
      </node>"""
    nodes = "\n".join([
        node.format(n=0, n1=1, sans="ans1", tans="Imin", tol=TOLERANCE, next=1,
                    fb="The smallest moment is not within 0.5 %: it is about the axis along the "
                       "longest edge, in kg m&sup2;."),
        node.format(n=1, n1=2, sans="ans2", tans="Imax", tol=TOLERANCE, next=-1,
                    fb="The largest moment is not within 0.5 %: it is about the axis along the "
                       "shortest edge, in kg m&sup2;."),
    ])
    inp = """    <input>
      <name>{name}</name>
      <type>numerical</type>
      <tans>{tans}</tans>
      <boxsize>12</boxsize>
      <strictsyntax>1</strictsyntax>
      <insertstars>0</insertstars>
      <syntaxhint></syntaxhint>
      <syntaxattribute>0</syntaxattribute>
      <forbidwords></forbidwords>
      <allowwords></allowwords>
      <forbidfloat>0</forbidfloat>
      <requirelowestterms>0</requirelowestterms>
      <checkanswertype>0</checkanswertype>
      <mustverify>1</mustverify>
      <showvalidation>1</showvalidation>
      <options></options>
    </input>"""
    return """<?xml version="1.0" encoding="UTF-8"?>
<!-- Moodle STACK question: principal moments of a box. Its Maxima question variables
     hold mechd's answers, written by docs/grading/moodle/make_stack.py (do not edit by
     hand). Import: Question bank > Import > Moodle XML. -->
<quiz>
  <question type="stack">
    <name><text>Principal moments of a box (answers from mechd)</text></name>
    <questiontext format="html">
      <text><![CDATA[<p>A uniform box of mass {{@m@}} kg has edges {{@a@}} m, {{@b@}} m and {{@c@}} m.
About its centre of mass, its smallest principal moment of inertia is [[input:ans1]] kg m&sup2;
[[validation:ans1]] and its largest is [[input:ans2]] kg m&sup2; [[validation:ans2]].</p>]]></text>
    </questiontext>
    <generalfeedback format="html"><text></text></generalfeedback>
    <defaultgrade>1</defaultgrade>
    <penalty>0.1</penalty>
    <hidden>0</hidden>
    <idnumber></idnumber>
    <stackversion><text>2023010400</text></stackversion>
    <questionvariables>
      <text><![CDATA[{variables}]]></text>
    </questionvariables>
    <specificfeedback format="html"><text>[[feedback:prt1]]</text></specificfeedback>
    <questionnote><text>{{@[m,a,b,c]@}}: {{@[Imin,Imax]@}}</text></questionnote>
    <questionsimplify>1</questionsimplify>
    <assumepositive>0</assumepositive>
    <assumereal>0</assumereal>
    <prtcorrect format="html"><text>Correct answer, well done.</text></prtcorrect>
    <prtpartiallycorrect format="html"><text>Your answer is partially correct.</text></prtpartiallycorrect>
    <prtincorrect format="html"><text>Incorrect answer.</text></prtincorrect>
    <multiplicationsign>dot</multiplicationsign>
    <sqrtsign>1</sqrtsign>
    <complexno>i</complexno>
    <inversetrig>cos-1</inversetrig>
    <logicsymbol>lang</logicsymbol>
    <matrixparens>[</matrixparens>
    <variantsselectionseed></variantsselectionseed>
{inputs}
    <prt>
      <name>prt1</name>
      <value>1.0000000</value>
      <autosimplify>1</autosimplify>
      <feedbackstyle>1</feedbackstyle>
      <feedbackvariables><text></text></feedbackvariables>
{nodes}
    </prt>
  </question>
</quiz>
""".format(variables=variables, inputs=inp.format(name="ans1", tans="Imin") + "\n" +
           inp.format(name="ans2", tans="Imax"), nodes=nodes)


if __name__ == "__main__":
    print(question(answers()), end="")
