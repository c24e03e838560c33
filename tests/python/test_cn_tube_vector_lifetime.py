"""A TubeVector bound into a ContractorNetwork stays a live, valid domain
whatever the user does to the vector: its components are objects of their
own (tv[i] is the component itself, shared), never a slot of the vector."""
import gc

import pytest
import sillage
from sillage import Function, Interval, IntervalVector, TDomain, Tube, TubeVector


def equal():
    return sillage.CtcFunction(Function(["a", "b"], "a - b"))


def test_components_assigned_in_place_stay_live():
    td = TDomain(0.0, 1.0, 0.5)
    tv = TubeVector(td, 2, Interval(-10, 10))
    cn = sillage.ContractorNetwork()
    cn.add(equal(), [tv[0], tv[1]])
    tv[0] = Tube(td, Interval(0, 1))  # assigns into the component
    tv &= TubeVector(td, IntervalVector([[-10, 10], [0.5, 2]]))
    assert not cn.contract().empty
    assert tv[0].codomain() == Interval(0.5, 1)
    assert tv[1].codomain() == Interval(0.5, 1)


def test_component_is_the_same_object_as_the_vector_slot():
    td = TDomain(0.0, 1.0, 0.5)
    tv = TubeVector(td, 2, Interval(-10, 10))
    c = tv[0]
    c.set(Interval(3))
    assert tv[0].codomain() == Interval(3)
    cn = sillage.ContractorNetwork()
    cn.add(equal(), [tv[0], tv[1]])
    cn.add(equal(), [sillage.DomainRef.component(tv, 0), tv[1]])
    assert cn.nb_dom() == 2  # tv[0] and DomainRef.component(tv, 0): one domain


def test_rebinding_the_name_keeps_the_bound_vector():
    td = TDomain(0.0, 1.0, 0.5)
    tv = TubeVector(td, 2, Interval(-10, 10))
    first = tv[0]
    cn = sillage.ContractorNetwork()
    cn.add(equal(), [tv[0], tv[1]])
    second = tv[1]
    tv = TubeVector(td, IntervalVector([[0, 1], [0.5, 2]]))  # a new vector; the network keeps the old one
    gc.collect()
    second.set(Interval(0.5, 2))
    first.set(Interval(0, 1))
    assert not cn.contract().empty
    assert first.codomain() == Interval(0.5, 1)
    assert tv[0].codomain() == Interval(0, 1)  # the new vector is not in the network


def test_python_contractor_cannot_grow_the_network_during_contract():
    cn = sillage.ContractorNetwork()
    x = cn.create_dom(Interval(0, 1))

    class Grow(sillage.Ctc):
        def __init__(self):
            super().__init__(1)

        def contract(self, box):
            cn.create_dom(Interval(0, 1))

    cn.add(Grow(), [x])
    with pytest.raises(sillage.Error, match="add_domain: called during contract"):
        cn.contract()
    cn.create_dom(Interval(2, 3))  # allowed again after
    assert cn.nb_dom() == 2


def test_sampling_the_tdomain_during_contract_is_an_error():
    td = TDomain(0.0, 1.0, 0.5)
    tv = TubeVector(td, 2, Interval(-10, 10))

    class Sampler(sillage.Ctc):
        def __init__(self):
            super().__init__(1)

        def contract(self, box):
            if td.nb_slices() == 2:
                td.sample(0.25)

    cn = sillage.ContractorNetwork()
    cn.add(equal(), [tv])
    cn.add(Sampler(), [Interval(0, 1)])
    with pytest.raises(sillage.DimensionError, match="changed during contract"):
        cn.contract()
